#if PEER_BEPU
using System.Numerics;
using BepuPhysics;
using BepuUtilities;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// Bepu's velocity-integration hook: gravity only, no damping. Angular motion is integrated
    /// without the gyroscopic term, as Fulcrum's TGS substeps do.
    /// </summary>
    public struct BepuGravityCallbacks : IPoseIntegratorCallbacks
    {
        readonly Vector3 _gravity;
        Vector3Wide _gravityDt;

        public BepuGravityCallbacks(Vector3 gravity)
        {
            _gravity = gravity;
            _gravityDt = default;
        }

        public readonly AngularIntegrationMode AngularIntegrationMode => AngularIntegrationMode.Nonconserving;
        public readonly bool AllowSubstepsForUnconstrainedBodies => false;
        public readonly bool IntegrateVelocityForKinematics => false;

        public void Initialize(Simulation simulation) { }

        public void PrepareForIntegration(float dt) => _gravityDt = Vector3Wide.Broadcast(_gravity * dt);

        public void IntegrateVelocity(Vector<int> bodyIndices, Vector3Wide position, QuaternionWide orientation, BodyInertiaWide localInertia,
            Vector<int> integrationMask, int workerIndex, Vector<float> dt, ref BodyVelocityWide velocity)
        {
            velocity.Linear += _gravityDt;
        }
    }
}
#endif
