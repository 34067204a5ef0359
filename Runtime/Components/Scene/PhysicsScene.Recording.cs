using System;
using System.Collections.Generic;
using System.IO;

namespace Fulcrum.Components
{
    // Recording a components scene to a .frec file for the browser viewer: the scene owns the
    // Recorder and writes a frame after every fixed step, on the thread that ticks it.
    public sealed partial class PhysicsScene
    {
        Recorder? _recorder;

        /// <summary>The recorder of the recording in progress, or null (see <see cref="StartRecording"/>).</summary>
        public Recorder? recorder => _recorder;

        /// <summary>
        /// Starts a <c>.frec</c> recording (Documentation~/RecordingFormat.md) of this scene to
        /// <paramref name="stream"/>: the header and a frame of the state now, then one frame
        /// after every fixed step (<see cref="Tick"/> and <see cref="Simulate"/>) until
        /// <see cref="StopRecording"/>. Bodies are named after their entities. What exists now
        /// is what is recorded (see <see cref="Recorder"/>): start once the scene is built.
        /// Recording does not change the simulation.
        /// </summary>
        /// <param name="stream">A writable stream (a file, a socket's stream, memory).</param>
        /// <param name="ownsStream">Whether <see cref="StopRecording"/> closes the stream.</param>
        /// <returns>The recorder (its counters; set <see cref="Recorder.Enabled"/> to pause).</returns>
        public Recorder StartRecording(Stream stream, bool ownsStream = false)
        {
            if (stream == null) throw new ArgumentNullException(nameof(stream), "PhysicsScene.StartRecording: stream cannot be null.");
            if (_recorder != null) throw new InvalidOperationException("PhysicsScene.StartRecording: a recording is already running; call StopRecording first.");
            Dictionary<BodyHandle, string> names = BodyNames();
            _recorder = new Recorder(_world, _stepper.FixedDt, stream, ownsStream,
                h => names.TryGetValue(h, out string? n) ? n : null);
            _recorder.Record();
            return _recorder;
        }

        /// <summary>Ends the recording in progress (flushing the stream, closing it if the scene owns it); does nothing without one.</summary>
        public void StopRecording()
        {
            Recorder? r = _recorder;
            _recorder = null;
            r?.Dispose();
        }

        // After each fixed step, once the poses are final (axis locks applied).
        void RecordStep() => _recorder?.Record();

        Dictionary<BodyHandle, string> BodyNames()
        {
            var names = new Dictionary<BodyHandle, string>();
            for (int k = 0; k < _rigidbodies.Count; k++)
                if (_rigidbodies[k].HasBody) names[_rigidbodies[k].body] = _rigidbodies[k].name;
            for (int k = 0; k < _colliders.Count; k++)
            {
                Collider c = _colliders[k];
                if (c.HasShape && !names.ContainsKey(c.Body)) names[c.Body] = c.name;
            }
            return names;
        }
    }
}
