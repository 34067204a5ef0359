namespace Fulcrum
{
    /// <summary>
    /// The stages of <see cref="World.Step"/>, in run order. The stage methods, the profiler
    /// buckets (<see cref="StepProfile"/>) and DESIGN.md use these names.
    /// </summary>
    public enum StepStage
    {
        /// <summary>Refit moving shapes' bounds in the dynamic AABB trees; find candidate pairs.</summary>
        BroadPhase = 0,
        /// <summary>Run the pair functions; update persistent contact manifolds.</summary>
        NarrowPhase = 1,
        /// <summary>Union-find over contacts and joints: islands, solver batches.</summary>
        Islands = 2,
        /// <summary>Integrate velocities, solve contacts and joints, integrate positions.</summary>
        Solve = 3,
        /// <summary>XPBD substeps of soft bodies, coupled to rigid shapes (only if any exist).</summary>
        SoftBodies = 4,
        /// <summary>Time of impact for bodies that asked for continuous collision.</summary>
        Continuous = 5,
        /// <summary>Sleep timers, contact begin/persist/end and trigger events, broken joints.</summary>
        SleepAndEvents = 6,
    }
}
