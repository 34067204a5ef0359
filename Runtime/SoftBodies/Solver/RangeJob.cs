namespace Fulcrum.SoftBodies
{
    /// <summary>Work over an index range, run in chunks by the world's <see cref="IParallelScheduler"/>.</summary>
    internal abstract class RangeJob : IParallelJob
    {
        /// <summary>Processes indices [start, end).</summary>
        public abstract void Execute(int start, int end);
    }
}
