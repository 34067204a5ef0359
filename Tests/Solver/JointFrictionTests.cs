using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>
    /// Joint friction (JointDef.FrictionTorque) and why ragdolls need it: a frictionless limb
    /// hanging at a cone limit is a conservative pendulum sliding round the cone's rim.
    /// </summary>
    public class JointFrictionTests
    {
        const float Dt = 1f / 60f;
        const float G = 9.81f;

        // A 6 kg head (capsule r 0.1) on a cone-twist joint whose axis is horizontal: it drops
        // onto the 40 deg cone and slides round its rim, a pendulum with nothing to damp it.
        static (World w, BodyHandle head) HangingHead(SolverType solver, float frictionTorque)
        {
            WorldSettings s = Settings(solver);
            var w = new World(s);
            BodyDef d = BodyDef.Dynamic(new Vector3(0.13f, 2f, 0));
            d.Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, -MathF.PI / 2);
            d.LinearVelocity = new Vector3(0, 0, 0.3f);
            BodyHandle head = w.CreateBody(d);
            ShapeDef shape = ShapeDef.Of(ShapeGeometry.Capsule(0.1f, 0.03f));
            shape.Density = 1000;
            w.AddShape(head, shape);
            JointDef j = JointDef.ConeTwist(BodyHandle.None, head, new Vector3(0, 2f, 0), new Vector3(0, -0.13f, 0), Vector3.UnitX, Vector3.UnitY, 40, 40);
            j.FrictionTorque = frictionTorque;
            w.CreateJoint(j);
            return (w, head);
        }

        static float Energy(World w, BodyHandle h)
        {
            var b = w.GetBody(h);
            return b.KineticEnergy + b.Mass * G * b.CenterOfMass.Y;
        }

        // The energy the cone limit absorbs in the first drop is gone; what is left must neither
        // grow (a solver that pumps energy into limits) nor vanish (the head keeps swinging:
        // without friction nothing at rest can be expected).
        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Head_sliding_round_a_frictionless_cone_limit_keeps_its_energy_and_swings_on(SolverType solver)
        {
            (World w, BodyHandle head) = HangingHead(solver, 0);
            for (int n = 0; n < 120; n++) w.Step(Dt);
            float e2 = Energy(w, head), eMax = e2, eMin = e2, lateSpin = 0;
            for (int n = 120; n < 600; n++)
            {
                w.Step(Dt);
                float e = Energy(w, head);
                eMax = MathF.Max(eMax, e);
                eMin = MathF.Min(eMin, e);
                if (n >= 480) lateSpin = MathF.Max(lateSpin, w.GetBody(head).AngularVelocity.Length());
            }
            // The swing's own energy: above the lowest point of the rim, about 1 J.
            TestContext.Out.WriteLine($"{solver}: energy from 2 s to 10 s between {eMin - e2:F4} and {eMax - e2:+0.0000;-0.0000} J of the value at 2 s; spin in the last 2 s up to {lateSpin:F2} rad/s");
            Assert.That(eMax - e2, Is.LessThan(0.02f), "a limit never adds energy");
            Assert.That(e2 - eMin, Is.LessThan(0.5f));
            Assert.That(lateSpin, Is.GreaterThan(0.5f), "no friction: the head still swings");
        }

        [TestCase(SolverType.Tgs)]
        [TestCase(SolverType.Pgs)]
        public void Head_on_a_cone_twist_joint_with_friction_stops_and_sleeps(SolverType solver)
        {
            (World w, BodyHandle head) = HangingHead(solver, 0.5f);
            int asleepAt = -1;
            for (int n = 0; n < 600 && asleepAt < 0; n++)
            {
                w.Step(Dt);
                if (!w.GetBody(head).IsAwake) asleepAt = n;
            }
            TestContext.Out.WriteLine($"{solver}: asleep after {asleepAt * Dt:F2} s");
            Assert.That(asleepAt, Is.GreaterThan(0));
            Assert.That(asleepAt * Dt, Is.LessThan(5f));
        }

        // A 1 kg, 0.5 m horizontal arm on a hinge with a horizontal axis: gravity's torque about
        // the hinge is m g L/2 = 2.45 N m. Friction above it holds the arm; below it, it slips.
        [TestCase(SolverType.Tgs, 3.0f, true)]
        [TestCase(SolverType.Tgs, 2.0f, false)]
        [TestCase(SolverType.Pgs, 3.0f, true)]
        [TestCase(SolverType.Pgs, 2.0f, false)]
        public void Hinge_friction_holds_a_horizontal_arm_only_above_the_gravity_torque(SolverType solver, float frictionTorque, bool holds)
        {
            var w = new World(Settings(solver));
            BodyHandle arm = Box(w, new Vector3(0.25f, 1, 0), new Vector3(0.25f, 0.02f, 0.02f), 1f);
            JointDef j = JointDef.Hinge(BodyHandle.None, arm, new Vector3(0, 1, 0), new Vector3(-0.25f, 0, 0), Vector3.UnitZ, Vector3.UnitZ);
            j.FrictionTorque = frictionTorque;
            w.CreateJoint(j);
            for (int n = 0; n < 60; n++) w.Step(Dt);
            Vector3 tip = w.GetBody(arm).CenterOfMass;
            float dropDeg = MathF.Atan2(1 - tip.Y, tip.X) * 180f / MathF.PI;
            TestContext.Out.WriteLine($"{solver}, friction {frictionTorque} N m against 2.45 N m: the arm dropped {dropDeg:F3} deg in 1 s");
            if (holds) Assert.That(dropDeg, Is.LessThan(0.5f));
            else Assert.That(dropDeg, Is.GreaterThan(20f));
        }

        [Test]
        public void Negative_friction_torque_is_rejected_naming_the_field()
        {
            var w = new World(WorldSettings.Default);
            BodyHandle b = Box(w, Vector3.Zero, new Vector3(0.5f), 1f);
            JointDef j = JointDef.Ball(BodyHandle.None, b, Vector3.Zero, Vector3.Zero);
            j.FrictionTorque = -1;
            var e = Assert.Throws<ArgumentException>(() => w.CreateJoint(j));
            Assert.That(e!.Message, Does.Contain("joint.FrictionTorque"));
            Assert.That(w.JointCount, Is.EqualTo(0));
        }
    }
}
