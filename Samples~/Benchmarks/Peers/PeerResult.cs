namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>What one engine measured on one scene.</summary>
    public sealed class PeerResult
    {
        public string Engine { get; init; } = "";
        public string Scene { get; init; } = "";
        public int Bodies { get; init; }
        /// <summary>Median time of a timed step on <see cref="ThreadClock"/> (thread CPU time where available), ms.</summary>
        public double MedianMs { get; init; }
        /// <summary>95th percentile of the same, ms.</summary>
        public double P95Ms { get; init; }
        /// <summary>Median wall time of a timed step, ms (includes time slices lost to other processes).</summary>
        public double WallMedianMs { get; init; }
        /// <summary>Managed bytes the stepping thread allocated per timed step (mean).</summary>
        public double BytesPerStep { get; init; }
        /// <summary>Horizontal distance of the tracked box from its start x/z at the end, m (NaN: no tracked box).</summary>
        public double Drift { get; init; }
        /// <summary>Start height minus end height of the tracked box, m (NaN: no tracked box).</summary>
        public double Sink { get; init; }
        /// <summary>Deepest any box's lowest corner went below the ground top, over every step, m.</summary>
        public double MaxGroundPenetration { get; init; }
        /// <summary>Whether every box stayed finite.</summary>
        public bool Finite { get; init; }
    }
}
