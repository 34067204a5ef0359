namespace Fulcrum
{
    /// <summary>
    /// The parallel-for that a step's stages (the solver's colour batches and body passes, the
    /// narrow phase's pair functions, the soft bodies' element colours) use when
    /// <see cref="WorldSettings.Threads"/> &gt; 1. The world's own one is a pool of
    /// <see cref="WorldSettings.Threads"/> - 1 background threads; a host that has threads of its
    /// own (Unity's job system, a game's task pool) can plug them in through
    /// <see cref="World.Scheduler"/>. The results do not depend on the scheduler: every call's
    /// chunks write disjoint data.
    /// </summary>
    public interface IParallelScheduler
    {
        /// <summary>Threads that take part in a call, the caller included (at least 1; used to size chunks).</summary>
        int ThreadCount { get; }

        /// <summary>
        /// Runs <paramref name="job"/> over [<paramref name="start"/>, <paramref name="end"/>)
        /// and returns when every item is done. The range may be split into chunks of at least
        /// <paramref name="minChunk"/> items (smaller ones cost more to hand out than they
        /// save), each run exactly once on any thread, the caller's included; a scheduler may
        /// also run the whole range on the caller. Called many times per step (once per colour
        /// batch, microseconds each): it should allocate nothing and wake threads cheaply.
        /// </summary>
        void For(IParallelJob job, int start, int end, int minChunk);
    }
}
