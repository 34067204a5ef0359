using System;
using System.Numerics;
using Fulcrum;
using Fulcrum.Mathematics;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>
    /// Rotation of bodies that the TGS substeps integrate (bodies in a constraint): with
    /// unequal principal moments the angular velocity must turn with the body so that the
    /// angular momentum is kept (the gyroscopic terms), as it is for free bodies.
    /// </summary>
    public class ConstrainedRotationTests
    {
        const float Dt = 1f / 60f;

        static Vector3 AngularMomentum(World w, BodyHandle h)
        {
            Assert.That(w.Bodies.InverseInertiaWorld[h.Index].TryInvert(out Mat3 inertia), Is.True);
            return inertia * w.GetBody(h).AngularVelocity;
        }

        // A 1 x 0.2 x 0.5 m box spun mostly about its long-moment axis, held at its centre of
        // mass by a ball joint in zero gravity: the joint's force passes through the centre, so
        // no torque acts and L is constant (before the fix TGS kept w instead: 6.5 % off in 10 s).
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Box_spinning_on_a_ball_joint_at_its_centre_keeps_its_angular_momentum(SolverType solver)
        {
            WorldSettings s = Settings(solver);
            s.Gravity = Vector3.Zero;
            s.EnableSleeping = false;
            var w = new World(s);
            BodyDef d = BodyDef.Dynamic(new Vector3(0, 2, 0));
            d.AngularVelocity = new Vector3(0.2f, 5f, 0.3f);
            BodyHandle box = w.CreateBody(d);
            w.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f, 0.1f, 0.25f))));
            w.CreateJoint(JointDef.Ball(BodyHandle.None, box, new Vector3(0, 2, 0), Vector3.Zero));
            Vector3 l0 = AngularMomentum(w, box);
            float worst = 0;
            for (int n = 0; n < 600; n++)
            {
                w.Step(Dt);
                worst = MathF.Max(worst, (AngularMomentum(w, box) - l0).Length() / l0.Length());
            }
            TestContext.Out.WriteLine($"{solver}: largest |L - L0| / |L0| over 10 s {worst * 100:F3} %");
            Assert.That(worst, Is.LessThan(0.005f));
        }
    }
}
