using System;
using System.Threading;

namespace Fulcrum.Tests.Components
{
    /// <summary>Measures what a warm loop allocates on this thread.</summary>
    public static class AllocationProbe
    {
        /// <summary>
        /// Runs <paramref name="frame"/> to warm it up, then returns the fewest bytes allocated by
        /// 200 frames in any of three windows. The runtime's tiered JIT may allocate a few bytes
        /// once while it recompiles hot methods in the background; a real per-frame allocation
        /// shows in every window.
        /// </summary>
        public static long SteadyStateBytes(Action frame)
        {
            for (int k = 0; k < 200; k++) frame();
            Thread.Sleep(150); // let the background tier-1 compiles finish
            for (int k = 0; k < 200; k++) frame();
            long best = long.MaxValue;
            for (int w = 0; w < 3; w++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                for (int k = 0; k < 200; k++) frame();
                best = Math.Min(best, GC.GetAllocatedBytesForCurrentThread() - before);
            }
            return best;
        }
    }
}
