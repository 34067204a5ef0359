namespace Fulcrum
{
    /// <summary>
    /// The hook through which the soft-body assembly (Fulcrum.SoftBodies) joins a world's step
    /// without Core depending on it: a world with no soft bodies never loads that assembly.
    /// </summary>
    public interface ISoftBodyStage
    {
        /// <summary>True when there is at least one soft body to step.</summary>
        bool HasWork { get; }

        /// <summary>Runs the <see cref="StepStage.SoftBodies"/> stage for one step of <paramref name="dt"/> seconds.</summary>
        void Step(World world, float dt);
    }
}
