namespace Fulcrum.Dynamics
{
    /// <summary>Work over an index range that <see cref="WorkerPool"/> can split between threads.</summary>
    internal interface IRangeJob
    {
        /// <summary>Does the items [<paramref name="start"/>, <paramref name="end"/>).</summary>
        void Execute(int start, int end);
    }
}
