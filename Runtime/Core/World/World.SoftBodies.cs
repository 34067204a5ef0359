namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// <see cref="StepStage.SoftBodies"/>: the XPBD (or Newton) substeps of the soft bodies,
        /// coupled to the rigid shapes, run by the soft-body assembly through
        /// <see cref="SoftBodyStage"/>; skipped when there is none or it has no work.
        /// Reads: the rigid bodies' poses and velocities before and after the solve (start
        /// velocities, <see cref="IntegratorSubsteps"/>), shapes and the broad-phase trees.
        /// Writes: the soft bodies' particles, and the rigid bodies' velocities and poses where
        /// the coupling pushes them.
        /// </summary>
        void SoftBodies(float dt)
        {
            if (SoftBodyStage != null && SoftBodyStage.HasWork) SoftBodyStage.Step(this, dt);
        }
    }
}
