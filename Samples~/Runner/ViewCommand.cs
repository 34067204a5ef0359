using System;
using System.IO;
using System.Net;
using System.Net.Sockets;
using System.Threading;

namespace Fulcrum.Runner;

/// <summary>
/// <c>fulcrum view [OUT.frec] [--port N] [--viewer DIR]</c>: serves the built browser viewer
/// (Viewer~/dist) and the recording on http://127.0.0.1:PORT/ until stopped with Ctrl+C.
/// The viewer loads <c>/recording.frec</c> when the page says a file is being served;
/// without a file it waits for one to be dropped on the page.
/// Only the loopback address is bound: the server is for the person at this machine.
/// </summary>
static class ViewCommand
{
    public static readonly string[] Flags = { "--port", "--viewer" };

    /// <summary>The port tried first; the next ones are tried when it is taken.</summary>
    public const int DefaultPort = 8765;

    /// <summary>The path the recording is served at.</summary>
    public const string RecordingPath = "/recording.frec";

    public static int Run(Arguments a, TextWriter output, CancellationToken stop = default)
    {
        if (a.Positional.Count > 1) throw new UsageException($"view: unexpected argument '{a.Positional[1]}'");
        string? file = a.Positional.Count == 1 ? a.Positional[0] : null;
        if (file != null && !File.Exists(file)) throw new UsageException($"{file}: no such recording", Cli.ExitScene);
        if (file != null) CheckMagic(file);
        int? port = a.Int("--port", 1, 65535, "a TCP port");
        string dist = FindViewer(a.String("--viewer"));

        HttpListener listener = Listen(port, out int bound);
        string url = $"http://127.0.0.1:{bound}/" + (file != null ? "?file=" + Uri.EscapeDataString(RecordingPath.TrimStart('/')) + "&name=" + Uri.EscapeDataString(Path.GetFileName(file)) : "");
        output.WriteLine($"viewer: {dist}");
        if (file != null) output.WriteLine($"recording: {file}");
        output.WriteLine($"serving {url}  (Ctrl+C to stop)");
        output.Flush();
        using (stop.Register(() => Stop(listener)))
        {
            ConsoleCancelEventHandler onCtrlC = (_, e) => { e.Cancel = true; Stop(listener); };
            Console.CancelKeyPress += onCtrlC;
            while (listener.IsListening)
            {
                HttpListenerContext context;
                try { context = listener.GetContext(); }
                catch (Exception e) when (e is HttpListenerException or ObjectDisposedException or InvalidOperationException) { break; }
                Serve(context, dist, file);
            }
            Console.CancelKeyPress -= onCtrlC;
        }
        listener.Close();
        return Cli.ExitOk;
    }

    internal static void Stop(HttpListener listener)
    {
        try { listener.Stop(); }
        catch (ObjectDisposedException) { }
    }

    static void CheckMagic(string file)
    {
        var head = new byte[4];
        using (FileStream s = File.OpenRead(file))
            if (s.Read(head, 0, 4) != 4 || !head.AsSpan().SequenceEqual(RecordingFormat.Magic))
                throw new UsageException($"{file}: not a Fulcrum recording (write one with 'fulcrum run SCENE.json --record {file}')", Cli.ExitScene);
    }

    /// <summary>The built viewer: --viewer DIR, else Viewer~/dist above the current folder or above this program.</summary>
    internal static string FindViewer(string? given)
    {
        if (given != null)
        {
            string dir = File.Exists(Path.Combine(given, "index.html")) ? given : Path.Combine(given, "dist");
            if (!File.Exists(Path.Combine(dir, "index.html"))) throw new UsageException($"--viewer: no index.html in '{given}' (build it: cd Viewer~ && npm ci && npm run build)");
            return Path.GetFullPath(dir);
        }
        foreach (string start in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
            for (DirectoryInfo? d = new DirectoryInfo(start); d != null; d = d.Parent)
            {
                string dist = Path.Combine(d.FullName, "Viewer~", "dist");
                if (File.Exists(Path.Combine(dist, "index.html"))) return dist;
            }
        throw new UsageException("view: the viewer is not built (cd Viewer~ && npm ci && npm run build), or give --viewer DIR");
    }

    internal static HttpListener Listen(int? port, out int bound)
    {
        int first = port ?? DefaultPort, tries = port != null ? 1 : 20;
        for (int p = first; p < first + tries; p++)
        {
            var listener = new HttpListener();
            listener.Prefixes.Add($"http://127.0.0.1:{p}/");
            try
            {
                listener.Start();
                bound = p;
                return listener;
            }
            catch (Exception e) when (e is HttpListenerException or SocketException)
            {
                listener.Close();
            }
        }
        throw new UsageException(port != null ? $"--port: {port} is in use" : $"view: ports {first}..{first + tries - 1} are all in use; give --port N");
    }

    internal static void Serve(HttpListenerContext context, string dist, string? file)
    {
        HttpListenerResponse response = context.Response;
        try
        {
            string path = Uri.UnescapeDataString(context.Request.Url?.AbsolutePath ?? "/");
            string? local = path == RecordingPath ? file
                : path == "/" ? Path.Combine(dist, "index.html")
                : Path.GetFullPath(Path.Combine(dist, path.TrimStart('/')));
            // Nothing outside the viewer's folder (and the one recording) is served.
            bool allowed = local != null && (local == file || local.StartsWith(dist + Path.DirectorySeparatorChar, StringComparison.Ordinal));
            if (!allowed || !File.Exists(local))
            {
                response.StatusCode = 404;
                return;
            }
            response.ContentType = ContentType(local!);
            response.Headers["Cache-Control"] = "no-store";
            using FileStream s = File.OpenRead(local!);
            response.ContentLength64 = s.Length;
            s.CopyTo(response.OutputStream);
        }
        catch (Exception e) when (e is IOException or HttpListenerException or UnauthorizedAccessException)
        {
            // The browser went away mid-transfer, or the file vanished: nothing to tell anyone.
        }
        finally
        {
            try { response.Close(); } catch (Exception e) when (e is HttpListenerException or ObjectDisposedException) { }
        }
    }

    static string ContentType(string path) => Path.GetExtension(path).ToLowerInvariant() switch
    {
        ".html" => "text/html; charset=utf-8",
        ".js" or ".mjs" => "text/javascript; charset=utf-8",
        ".css" => "text/css; charset=utf-8",
        ".svg" => "image/svg+xml",
        ".png" => "image/png",
        ".json" => "application/json",
        _ => "application/octet-stream",
    };
}
