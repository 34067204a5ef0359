namespace Fulcrum
{
    /// <summary>A step stage with worker threads of its own, which <see cref="World.StopThreads"/> ends too.</summary>
    internal interface IThreadedStage
    {
        /// <summary>Ends the stage's worker threads; the stage starts new ones if a later step needs them.</summary>
        void StopThreads();
    }
}
