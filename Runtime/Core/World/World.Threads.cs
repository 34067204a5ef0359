namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Ends the worker threads the world started for <see cref="WorldSettings.Threads"/> &gt; 1
        /// (solver and soft-body workers). A later step with several threads starts new ones.
        /// Call it when a host is done with the world (Unity's play mode ending, with domain
        /// reload off, would otherwise keep the idle threads until the editor quits). Not during a step.
        /// </summary>
        public void StopThreads()
        {
            ThrowIfInStep();
            _workers?.Stop();
            _workers = null;
            (SoftBodyStage as IThreadedStage)?.StopThreads();
        }
    }
}
