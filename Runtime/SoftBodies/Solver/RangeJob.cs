namespace Fulcrum.SoftBodies
{
    /// <summary>Work over an index range, run in chunks by <see cref="ParallelRanges"/>.</summary>
    internal abstract class RangeJob
    {
        /// <summary>Processes indices [start, end).</summary>
        public abstract void Execute(int start, int end);
    }
}
