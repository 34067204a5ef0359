using System;
using System.IO;
using System.Threading;

namespace Fulcrum.Components
{
    // Recording the bridge's world to a .frec file for the browser viewer. The recorder reads
    // the world, so it lives on the thread that steps: the caller's without a physics thread;
    // with one, start and stop are requests the physics thread takes up between its steps
    // (under _sync, like the commands), and StopRecording waits for it to close the recording.
    public sealed partial class PhysicsBridge
    {
        Recorder? _recorder;           // stepping side
        bool _gRecording;              // game side: a recording was started and not stopped
        // Requests to the physics thread, under _sync.
        Stream? _recordStart;
        bool _recordStartOwns;
        bool _recordStop;
        Exception? _recordError;

        /// <summary>
        /// Starts a <c>.frec</c> recording (Documentation~/RecordingFormat.md) of the bridge's
        /// world to <paramref name="stream"/>: the header and a frame of the state now, then one
        /// frame after every step, written on the thread that steps. Without a physics thread it
        /// starts at once; with one, before the thread's next step (bodies registered before
        /// this call are in it). What exists then is what is recorded (see <see cref="Recorder"/>).
        /// Recording does not change the simulation.
        /// </summary>
        /// <param name="stream">A writable stream; with a physics thread, do not touch it until <see cref="StopRecording"/> returns.</param>
        /// <param name="ownsStream">Whether stopping closes the stream.</param>
        public void StartRecording(Stream stream, bool ownsStream = false)
        {
            ThrowIfDisposed();
            ThrowIfDispatching(nameof(StartRecording));
            if (stream == null) throw new ArgumentNullException(nameof(stream), "PhysicsBridge.StartRecording: stream cannot be null.");
            if (!stream.CanWrite) throw new ArgumentException("PhysicsBridge.StartRecording: the stream is not writable.", nameof(stream));
            if (_gRecording) throw new InvalidOperationException("PhysicsBridge.StartRecording: a recording is already running; call StopRecording first.");
            if (_threaded)
            {
                ThrowIfThreadFailed();
                lock (_sync)
                {
                    _recordStart = stream;
                    _recordStartOwns = ownsStream;
                    _recordError = null;
                }
            }
            else
            {
                _recorder = new Recorder(_world, _stepper.FixedDt, stream, ownsStream);
                _recorder.Record();
            }
            _gRecording = true;
        }

        /// <summary>True between <see cref="StartRecording"/> and <see cref="StopRecording"/>.</summary>
        public bool IsRecording => _gRecording;

        /// <summary>
        /// Ends the recording: the stream is flushed (and closed if the bridge owns it) when this
        /// returns. With a physics thread it waits for the thread's next step. Rethrows an error
        /// the physics thread met while writing (the recording stopped there; the simulation went on).
        /// Does nothing when no recording runs.
        /// </summary>
        public void StopRecording()
        {
            ThrowIfDisposed();
            ThrowIfDispatching(nameof(StopRecording));
            if (!_gRecording) return;
            _gRecording = false;
            if (!_threaded)
            {
                CloseRecorder();
                return;
            }
            Exception? error;
            bool threadGone;
            lock (_sync)
            {
                _recordStop = true;
                // The thread acknowledges by clearing the flag; a thread that died cannot.
                while (_recordStop && Volatile.Read(ref _threadError) == null) Monitor.Wait(_sync, 20);
                threadGone = _recordStop;
                _recordStop = false;
                error = _recordError;
                _recordError = null;
            }
            if (threadGone)
            {
                // The physics thread is gone: the world is ours again.
                DropRecordRequest();
                CloseRecorder();
            }
            if (error != null) throw new IOException($"PhysicsBridge: the recording failed on the physics thread: {error.Message}", error);
        }

        // On the stepping thread, after each world step.
        void RecordStep()
        {
            if (_recorder == null) return;
            if (!_threaded)
            {
                _recorder.Record();
                return;
            }
            try { _recorder.Record(); }
            catch (Exception e) when (e is IOException || e is ObjectDisposedException || e is NotSupportedException)
            {
                FailRecording(e);
            }
        }

        // On the physics thread, after the commands of a tick are applied: a requested start.
        void TakeRecordStart()
        {
            Stream? stream;
            bool owns;
            lock (_sync)
            {
                stream = _recordStart;
                owns = _recordStartOwns;
                _recordStart = null;
            }
            if (stream == null) return;
            try
            {
                _recorder = new Recorder(_world, _stepper.FixedDt, stream, owns);
                _recorder.Record();
            }
            catch (Exception e) when (e is IOException || e is ObjectDisposedException || e is NotSupportedException || e is ArgumentException)
            {
                if (owns) stream.Dispose();
                FailRecording(e);
            }
        }

        // On the physics thread, at the end of a tick: a requested stop.
        void TakeRecordStop()
        {
            lock (_sync)
            {
                if (!_recordStop) return;
            }
            Exception? error = null;
            try { CloseRecorder(); }
            catch (Exception e) when (e is IOException || e is ObjectDisposedException) { error = e; }
            lock (_sync)
            {
                if (error != null) _recordError = error;
                _recordStop = false;
                Monitor.PulseAll(_sync);
            }
        }

        void FailRecording(Exception e)
        {
            Recorder? r = _recorder;
            _recorder = null;
            try { r?.Dispose(); }
            catch (Exception x) when (x is IOException || x is ObjectDisposedException) { } // already failing: the first error is the one to report
            lock (_sync) _recordError = e;
        }

        void CloseRecorder()
        {
            Recorder? r = _recorder;
            _recorder = null;
            r?.Dispose();
        }

        // A start the physics thread never took up: close the stream if it was handed over.
        void DropRecordRequest()
        {
            Stream? pending;
            bool owns;
            lock (_sync)
            {
                pending = _recordStart;
                owns = _recordStartOwns;
                _recordStart = null;
            }
            if (pending != null && owns) pending.Dispose();
        }
    }
}
