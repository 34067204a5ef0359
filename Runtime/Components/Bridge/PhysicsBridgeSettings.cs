using System;

namespace Fulcrum.Components
{
    /// <summary>How a <see cref="PhysicsBridge"/> steps. Start from <see cref="Default"/>.</summary>
    public struct PhysicsBridgeSettings
    {
        /// <summary>The fixed physics step, seconds (&gt; 0). Default: 1/60 s. With a physics thread, 1/<see cref="ThreadRateHz"/> is used instead.</summary>
        public float FixedDt;
        /// <summary>Most fixed steps one <see cref="PhysicsBridge.Step"/> may take (the rest is dropped). Default: 8.</summary>
        public int MaxStepsPerFrame;
        /// <summary>Blend the last two step poses in <see cref="PhysicsBridge.SyncToGame"/> (smooth, one step behind). Default: true.</summary>
        public bool Interpolate;
        /// <summary>
        /// 0 steps on the caller's thread inside <see cref="PhysicsBridge.Step"/>; a positive rate
        /// (Hz, e.g. 120 under a 60 Hz renderer) runs the world on its own thread at that rate with
        /// double-buffered poses. Default: 0.
        /// </summary>
        public float ThreadRateHz;
        /// <summary>Capacity of the haptics ring buffer, samples (0 turns the stream off). Default: 1024.</summary>
        public int HapticsCapacity;

        /// <summary>The defaults documented on each field.</summary>
        public static PhysicsBridgeSettings Default => new PhysicsBridgeSettings
        {
            FixedDt = 1f / 60f,
            MaxStepsPerFrame = 8,
            Interpolate = true,
            ThreadRateHz = 0,
            HapticsCapacity = 1024,
        };

        /// <summary>Throws an <see cref="ArgumentException"/> naming the first bad field.</summary>
        public readonly void Validate()
        {
            if (!(float.IsFinite(FixedDt) && FixedDt > 0)) throw new ArgumentException($"PhysicsBridgeSettings.FixedDt must be finite and > 0, got {FixedDt}.", nameof(FixedDt));
            if (MaxStepsPerFrame < 1) throw new ArgumentException($"PhysicsBridgeSettings.MaxStepsPerFrame must be >= 1, got {MaxStepsPerFrame}.", nameof(MaxStepsPerFrame));
            if (!(float.IsFinite(ThreadRateHz) && ThreadRateHz >= 0 && ThreadRateHz <= 10000)) throw new ArgumentException($"PhysicsBridgeSettings.ThreadRateHz must be 0 (no thread) or in (0, 10000], got {ThreadRateHz}.", nameof(ThreadRateHz));
            if (HapticsCapacity < 0) throw new ArgumentException($"PhysicsBridgeSettings.HapticsCapacity must be >= 0, got {HapticsCapacity}.", nameof(HapticsCapacity));
        }
    }
}
