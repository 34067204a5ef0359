using System;
using System.Collections.Generic;
using System.IO;
using System.Net;
using System.Net.WebSockets;
using System.Text;
using System.Threading;
using System.Threading.Tasks;

namespace Fulcrum.Runner;

/// <summary>
/// The server of <c>fulcrum run SCENE --live</c>: serves the browser viewer (Viewer~/dist) on
/// http://127.0.0.1:PORT/ as <c>fulcrum view</c> does, and streams the recording being written
/// to every viewer that opens the WebSocket at <see cref="SocketPath"/>.
/// <para>
/// Framing (Documentation~/RecordingFormat.md, "Live mode"): binary messages whose
/// concatenation is the <c>.frec</c> byte stream from its first byte, so a viewer that connects
/// late is sent everything so far first, and message boundaries carry no meaning (the server
/// sends whatever has accumulated in one message). When the run ends, one text message
/// <c>end</c> follows the last bytes. The whole recording is kept in memory for late viewers.
/// </para>
/// Only the loopback address is bound: the server is for the person at this machine.
/// </summary>
sealed class LiveServer : IDisposable
{
    /// <summary>The WebSocket's path.</summary>
    public const string SocketPath = "/live";

    /// <summary>The text message sent after the last bytes of a finished run.</summary>
    public const string EndMessage = "end";

    readonly HttpListener _listener;
    readonly string _dist;
    readonly object _sync = new();
    readonly List<Task> _clients = new();
    readonly List<Task> _pages = new();  // page and script requests being answered
    readonly CancellationTokenSource _stop = new();
    readonly Task _accepting;
    byte[] _data = new byte[1 << 16];   // append-only: bytes below _length never change
    int _length;
    bool _ended;
    TaskCompletionSource _changed = new(TaskCreationOptions.RunContinuationsAsynchronously);

    /// <summary>Starts serving <paramref name="dist"/> on <paramref name="port"/> (or the first free one from the view command's default).</summary>
    public LiveServer(string dist, int? port)
    {
        _dist = dist;
        _listener = ViewCommand.Listen(port, out int bound);
        Port = bound;
        _accepting = Task.Run(AcceptLoop);
    }

    /// <summary>The port bound.</summary>
    public int Port { get; }

    /// <summary>The page to open: the viewer in live mode.</summary>
    public string Url => $"http://127.0.0.1:{Port}/?live={Uri.EscapeDataString(SocketPath)}";

    /// <summary>Viewers connected so far (open or closed).</summary>
    public int ViewerCount { get { lock (_sync) return _clients.Count; } }

    /// <summary>Bytes of the recording so far.</summary>
    public long Length { get { lock (_sync) return _length; } }

    /// <summary>A write-only stream for the <see cref="Recorder"/>: what is written is sent to the viewers (and copied to <paramref name="copy"/> when given, for --record).</summary>
    public Stream OpenStream(Stream? copy) => new LiveStream(this, copy);

    /// <summary>Appends recording bytes and wakes the viewers' senders.</summary>
    public void Append(ReadOnlySpan<byte> bytes)
    {
        lock (_sync)
        {
            if (_ended) throw new InvalidOperationException("the live run has ended");
            if (_length + bytes.Length > _data.Length)
            {
                // A new array: senders keep reading the old one, whose bytes stay valid.
                var grown = new byte[Math.Max(2 * _data.Length, _length + bytes.Length)];
                Buffer.BlockCopy(_data, 0, grown, 0, _length);
                _data = grown;
            }
            bytes.CopyTo(_data.AsSpan(_length));
            _length += bytes.Length;
            Signal();
        }
    }

    /// <summary>Marks the run finished: viewers get the rest of the bytes, then <see cref="EndMessage"/>.</summary>
    public void End()
    {
        lock (_sync)
        {
            _ended = true;
            Signal();
        }
    }

    /// <summary>Waits (up to <paramref name="timeout"/>) until every connected viewer has been sent the whole finished recording.</summary>
    public bool WaitForViewers(TimeSpan timeout)
    {
        Task[] clients;
        lock (_sync) clients = _clients.ToArray();
        return Task.WaitAll(clients, timeout);
    }

    /// <summary>Stops serving and closes the viewers' sockets.</summary>
    public void Dispose()
    {
        _stop.Cancel();
        // Answer the page requests already taken before stopping the listener, which aborts
        // the responses in flight (a page asked for just as a --live-exit run ended came back
        // empty).
        Task[] pages;
        lock (_sync) pages = _pages.ToArray();
        try { Task.WaitAll(pages, TimeSpan.FromSeconds(2)); }
        catch (AggregateException) { }
        ViewCommand.Stop(_listener);
        try { _accepting.Wait(TimeSpan.FromSeconds(2)); }
        catch (AggregateException) { }
        WaitForViewers(TimeSpan.FromSeconds(2));
        _listener.Close();
        _stop.Dispose();
    }

    void Signal()
    {
        TaskCompletionSource changed = _changed;
        _changed = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        changed.TrySetResult();
    }

    async Task AcceptLoop()
    {
        while (!_stop.IsCancellationRequested)
        {
            HttpListenerContext context;
            try { context = await _listener.GetContextAsync().ConfigureAwait(false); }
            catch (Exception e) when (e is HttpListenerException or ObjectDisposedException or InvalidOperationException) { break; }
            if (context.Request.Url?.AbsolutePath == SocketPath && context.Request.IsWebSocketRequest)
            {
                Task client = Task.Run(() => ServeViewer(context));
                lock (_sync) _clients.Add(client);
            }
            else
            {
                Task page = Task.Run(() => ViewCommand.Serve(context, _dist, null));
                lock (_sync)
                {
                    _pages.RemoveAll(t => t.IsCompleted);
                    _pages.Add(page);
                }
            }
        }
    }

    // One viewer: everything so far, then each new stretch of bytes as it comes, then "end".
    async Task ServeViewer(HttpListenerContext context)
    {
        WebSocket socket;
        try { socket = (await context.AcceptWebSocketAsync(null).ConfigureAwait(false)).WebSocket; }
        catch (Exception e) when (e is WebSocketException or HttpListenerException or ObjectDisposedException) { return; }
        using (socket)
        {
            int sent = 0;
            try
            {
                while (!_stop.IsCancellationRequested && socket.State == WebSocketState.Open)
                {
                    byte[] data;
                    int length;
                    bool ended;
                    Task changed;
                    lock (_sync)
                    {
                        data = _data;
                        length = _length;
                        ended = _ended;
                        changed = _changed.Task;
                    }
                    if (length > sent)
                    {
                        await socket.SendAsync(new ArraySegment<byte>(data, sent, length - sent), WebSocketMessageType.Binary, true, _stop.Token).ConfigureAwait(false);
                        sent = length;
                        continue;
                    }
                    if (ended)
                    {
                        await socket.SendAsync(new ArraySegment<byte>(Encoding.ASCII.GetBytes(EndMessage)), WebSocketMessageType.Text, true, _stop.Token).ConfigureAwait(false);
                        // The viewer keeps the socket open; it is closed when the server stops.
                        await socket.CloseOutputAsync(WebSocketCloseStatus.NormalClosure, "run finished", _stop.Token).ConfigureAwait(false);
                        return;
                    }
                    await changed.WaitAsync(_stop.Token).ConfigureAwait(false);
                }
            }
            catch (Exception e) when (e is WebSocketException or OperationCanceledException or HttpListenerException or ObjectDisposedException)
            {
                // The viewer went away, or the server is stopping: nothing to tell anyone.
            }
        }
    }

    /// <summary>The recorder's end of the server: every write is appended (and copied to the --record file).</summary>
    sealed class LiveStream : Stream
    {
        readonly LiveServer _server;
        readonly Stream? _copy;

        public LiveStream(LiveServer server, Stream? copy)
        {
            _server = server;
            _copy = copy;
        }

        public override bool CanRead => false;
        public override bool CanSeek => false;
        public override bool CanWrite => true;
        public override long Length => _server.Length;
        public override long Position { get => _server.Length; set => throw new NotSupportedException(); }

        public override void Write(byte[] buffer, int offset, int count) => Write(buffer.AsSpan(offset, count));

        public override void Write(ReadOnlySpan<byte> buffer)
        {
            _copy?.Write(buffer);
            _server.Append(buffer);
        }

        public override void Flush() => _copy?.Flush();

        protected override void Dispose(bool disposing)
        {
            if (disposing) _copy?.Dispose();
            base.Dispose(disposing);
        }

        public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();
    }
}
