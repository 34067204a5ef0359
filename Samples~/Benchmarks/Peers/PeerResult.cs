namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>What one engine measured on one phase of one scene in one run.</summary>
    public sealed class PeerResult
    {
        public string Engine { get; init; } = "";
        /// <summary>The phase's row name (the scene's name when it has one phase).</summary>
        public string Scene { get; init; } = "";
        public int Bodies { get; init; }
        /// <summary>Threads the engine stepped with.</summary>
        public int Threads { get; init; }
        /// <summary>
        /// Whether the step times are the stepping thread's CPU time (one thread, where the OS
        /// gives it) or wall time (several threads: the workers' time would be missed).
        /// </summary>
        public bool CpuTime { get; init; }
        /// <summary>Mean time of a timed step, ms.</summary>
        public double MeanMs { get; init; }
        /// <summary>Median time of a timed step, ms.</summary>
        public double MedianMs { get; init; }
        /// <summary>95th percentile of the same, ms.</summary>
        public double P95Ms { get; init; }
        /// <summary>Mean wall time of a timed step, ms (includes time slices lost to other processes).</summary>
        public double WallMeanMs { get; init; }
        /// <summary>Median wall time of a timed step, ms (includes time slices lost to other processes).</summary>
        public double WallMedianMs { get; init; }
        /// <summary>CPU time of the whole process per timed step (mean, every thread), ms; NaN where not measured.</summary>
        public double ProcessCpuMs { get; init; }
        /// <summary>Fulcrum's own per-stage wall times (mean per step, ms, indexed by StepStage), or null for a peer.</summary>
        public double[]? StageMs { get; init; }
        /// <summary>Managed bytes the stepping thread allocated per timed step (mean).</summary>
        public double BytesPerStep { get; init; }
        /// <summary>
        /// Managed bytes the whole process allocated per timed step (mean): worker threads too,
        /// and the runtime's own background threads (tiered JIT), so a small figure can be theirs.
        /// </summary>
        public double ProcessBytesPerStep { get; init; }
        /// <summary>Horizontal distance of the tracked box from its start x/z at the end, m (NaN: no tracked box).</summary>
        public double Drift { get; init; }
        /// <summary>Start height minus end height of the tracked box, m (NaN: no tracked box).</summary>
        public double Sink { get; init; }
        /// <summary>Deepest any box's lowest corner went below the ground top, over the phase, m.</summary>
        public double MaxGroundPenetration { get; init; }
        /// <summary>Mean speed of the boxes in the phase's last step (position change over dt), m/s.</summary>
        public double EndSpeed { get; init; }
        /// <summary>Whether every box stayed finite.</summary>
        public bool Finite { get; init; }
    }
}
