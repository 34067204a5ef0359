using Fulcrum.Dynamics;

namespace Fulcrum
{
    public sealed partial class World
    {
        void BuildIslands() { }

        // Semi-implicit Euler: velocities from forces, then positions from the new velocities.
        void Solve(float dt)
        {
            Integrator.IntegrateVelocities(Bodies, _settings.Gravity, dt, _settings.MaxLinearSpeed);
            Integrator.IntegratePositions(Bodies, dt);
        }

        void UpdateSleep(float dt) { }
    }
}
