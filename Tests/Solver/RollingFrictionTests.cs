using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Solver
{
    /// <summary>The contact solver on a hand-built manifold: rolling resistance (no shape field feeds it yet).</summary>
    public class RollingFrictionTests
    {
        [Test]
        public void Rolling_resistance_slows_a_rolling_ball_by_at_most_its_torque()
        {
            // A 1 kg ball of radius 0.5 rolling at 2 rad/s on a fixed ground, normal +y, one point.
            const float m = 1f, r = 0.5f, rolling = 0.02f;
            float inertia = 0.4f * m * r * r;
            var bodies = new SolverBody[2];
            bodies[0] = new SolverBody { DeltaRotation = Quaternion.Identity };
            bodies[1] = new SolverBody
            {
                InverseMass = 1f / m,
                InverseInertia = Mat3.Diagonal(new Vector3(1f / inertia)),
                IsDynamic = 1,
                AngularVelocity = new Vector3(0, 0, -2f),
                LinearVelocity = new Vector3(2f * r, 0, 0),
                DeltaRotation = Quaternion.Identity,
            };
            var manifold = new ContactManifold { BodyA = 0, BodyB = 1, Normal = Vector3.UnitY, PointCount = 1, Friction = 0.5f, RollingFriction = rolling };
            manifold.Point0 = new ContactPoint { AnchorA = Vector3.Zero, AnchorB = new Vector3(0, -r, 0), Separation = 0, NormalImpulse = 9.81f / 60f };
            var constraint = new ContactConstraint();
            var points = new ContactConstraintPoint[4];
            Softness soft = Softness.Make(30, 10, 1f / 60f);
            var step = new ContactStep(1f / 60f, 60f, soft, soft, 1f, false, 3f, 0.005f, 1f);
            ContactSolver.Prepare(ref constraint, points, 0, ref manifold, 0, bodies, 0, 1, step);
            // Gravity for one step, then the solve: the normal impulse is m g dt, so the rolling
            // torque can remove at most rolling * m g dt / I of spin (the friction keeps it rolling).
            bodies[1].LinearVelocity += new Vector3(0, -9.81f / 60f, 0);
            ContactSolver.WarmStart(ref constraint, points, bodies);
            for (int i = 0; i < 20; i++) ContactSolver.Solve(ref constraint, points, bodies, step, false);
            float spin = -bodies[1].AngularVelocity.Z;
            Assert.That(spin, Is.LessThan(2f));
            // Rolling resistance takes rolling * N dt of angular momentum; friction shares it with
            // the linear motion so that the ball keeps rolling: dw = rolling N dt / (I + m r^2).
            float expected = 2f - rolling * m * 9.81f / 60f / (inertia + m * r * r);
            Assert.That(spin, Is.EqualTo(expected).Within(2e-3f));
            Assert.That(bodies[1].LinearVelocity.X, Is.EqualTo(spin * r).Within(1e-3f));
        }
    }
}
