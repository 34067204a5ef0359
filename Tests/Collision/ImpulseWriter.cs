using Fulcrum.Collision;

namespace Fulcrum.Tests.Collision
{
    /// <summary>
    /// Stands in for the solver in collision tests: a stage that runs inside Step after the
    /// solve and writes known impulses into the contact set, as the solver would.
    /// </summary>
    internal sealed class ImpulseWriter : ISoftBodyStage
    {
        public bool HasWork => true;

        public float NormalPerPoint = 1f;

        public void Step(World world, float dt)
        {
            ContactSet set = world.Contacts;
            for (int k = 0; k < set.ManifoldCount; k++)
                for (int i = 0; i < set[k].PointCount; i++)
                {
                    ref ContactPoint p = ref ContactManifold.Point(ref set[k], i);
                    p.NormalImpulse = NormalPerPoint * (1 + i);
                    p.AppliedImpulse = p.NormalImpulse;
                    p.TangentImpulse1 = 0.1f * i;
                    p.TangentImpulse2 = -0.2f * i;
                }
        }
    }
}
