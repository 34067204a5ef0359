namespace Fulcrum
{
    /// <summary>
    /// Work over an index range that an <see cref="IParallelScheduler"/> may split between
    /// threads. The step's jobs are objects the world keeps, so scheduling one allocates nothing.
    /// </summary>
    public interface IParallelJob
    {
        /// <summary>
        /// Does the items [<paramref name="start"/>, <paramref name="end"/>). Chunks of one call
        /// write disjoint data, so they may run on any threads in any order.
        /// </summary>
        void Execute(int start, int end);
    }
}
