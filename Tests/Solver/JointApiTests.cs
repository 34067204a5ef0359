using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>Joint creation, validation, handles and lifetime.</summary>
    public class JointApiTests
    {
        static (World w, BodyHandle a, BodyHandle b) TwoBodies()
        {
            var w = new World();
            return (w, Sphere(w, Vector3.Zero, 0.1f, 1f), Sphere(w, new Vector3(1, 0, 0), 0.1f, 1f));
        }

        static void ThrowsNaming(World w, JointDef d, string field)
        {
            int before = w.JointCount;
            var e = Assert.Throws<ArgumentException>(() => w.CreateJoint(d));
            Assert.That(e!.ParamName, Is.EqualTo(field));
            Assert.That(w.JointCount, Is.EqualTo(before));
        }

        [Test]
        public void A_joint_between_a_body_and_itself_is_rejected_naming_BodyB()
        {
            var (w, a, _) = TwoBodies();
            ThrowsNaming(w, JointDef.Ball(a, a, Vector3.Zero, Vector3.Zero), "joint.BodyB");
            ThrowsNaming(w, JointDef.Ball(BodyHandle.None, BodyHandle.None, Vector3.Zero, Vector3.Zero), "joint.BodyB");
        }

        [Test]
        public void Non_finite_anchors_and_axes_are_rejected_naming_the_field()
        {
            var (w, a, b) = TwoBodies();
            ThrowsNaming(w, JointDef.Ball(a, b, new Vector3(float.NaN, 0, 0), Vector3.Zero), "joint.AnchorA");
            ThrowsNaming(w, JointDef.Ball(a, b, Vector3.Zero, new Vector3(0, float.PositiveInfinity, 0)), "joint.AnchorB");
            ThrowsNaming(w, JointDef.Hinge(a, b, Vector3.Zero, Vector3.Zero, Vector3.Zero, Vector3.UnitX), "joint.AxisA");
            ThrowsNaming(w, JointDef.Hinge(a, b, Vector3.Zero, Vector3.Zero, Vector3.UnitX, new Vector3(float.NaN, 1, 0)), "joint.AxisB");
        }

        [Test]
        public void Limits_with_min_above_max_are_rejected_naming_the_field()
        {
            var (w, a, b) = TwoBodies();
            JointDef hinge = JointDef.Hinge(a, b, Vector3.Zero, Vector3.Zero, Vector3.UnitZ, Vector3.UnitZ);
            hinge.LowerDeg = 10;
            hinge.UpperDeg = -10;
            ThrowsNaming(w, hinge, "joint.LowerDeg");
            ThrowsNaming(w, JointDef.Distance(a, b, Vector3.Zero, Vector3.Zero, 2f, 1f), "joint.MinLength");
            JointDef slider = JointDef.Prismatic(a, b, Vector3.Zero, Vector3.Zero, Vector3.UnitX);
            slider.Lower = 1;
            slider.Upper = 0;
            ThrowsNaming(w, slider, "joint.Lower");
            JointDef cone = JointDef.ConeTwist(a, b, Vector3.Zero, Vector3.Zero, Vector3.UnitX, Vector3.UnitX, 200f, 10f);
            ThrowsNaming(w, cone, "joint.ConeDeg");
        }

        [TestCase(0f)]
        [TestCase(-5f)]
        [TestCase(float.NaN)]
        public void Breaking_thresholds_at_or_below_zero_are_rejected_naming_the_field(float threshold)
        {
            var (w, a, b) = TwoBodies();
            JointDef d = JointDef.Ball(a, b, Vector3.Zero, Vector3.Zero);
            d.BreakForce = threshold;
            ThrowsNaming(w, d, "joint.BreakForce");
            d = JointDef.Ball(a, b, Vector3.Zero, Vector3.Zero);
            d.BreakTorque = threshold;
            ThrowsNaming(w, d, "joint.BreakTorque");
        }

        [Test]
        public void A_stale_body_handle_throws_StaleHandleException()
        {
            var (w, a, b) = TwoBodies();
            w.DestroyBody(b);
            Assert.Throws<StaleHandleException>(() => w.CreateJoint(JointDef.Ball(a, b, Vector3.Zero, Vector3.Zero)));
            Assert.That(w.JointCount, Is.EqualTo(0));
        }

        [Test]
        public void Destroyed_joint_handle_goes_stale_and_its_slot_is_reused_with_a_new_generation()
        {
            var (w, a, b) = TwoBodies();
            JointHandle j = w.CreateJoint(JointDef.Ball(a, b, Vector3.Zero, Vector3.Zero));
            w.DestroyJoint(j);
            Assert.That(w.IsValid(j), Is.False);
            Assert.Throws<StaleHandleException>(() => w.DestroyJoint(j));
            Assert.Throws<StaleHandleException>(() => w.GetJointForce(j));
            JointHandle k = w.CreateJoint(JointDef.Ball(a, b, Vector3.Zero, Vector3.Zero));
            Assert.That(k.Index, Is.EqualTo(j.Index));
            Assert.That(k, Is.Not.EqualTo(j));
            Assert.Throws<StaleHandleException>(() => w.GetJointForce(j));
        }

        [Test]
        public void Destroying_a_body_destroys_its_joints()
        {
            var w = new World();
            BodyHandle a = Sphere(w, Vector3.Zero, 0.1f, 1f);
            BodyHandle b = Sphere(w, new Vector3(1, 0, 0), 0.1f, 1f);
            BodyHandle c = Sphere(w, new Vector3(2, 0, 0), 0.1f, 1f);
            JointHandle ab = w.CreateJoint(JointDef.Ball(a, b, Vector3.Zero, new Vector3(-1, 0, 0)));
            JointHandle bc = w.CreateJoint(JointDef.Ball(b, c, Vector3.Zero, new Vector3(-1, 0, 0)));
            JointHandle ca = w.CreateJoint(JointDef.Distance(c, a, Vector3.Zero, Vector3.Zero, -1, -1));
            w.DestroyBody(b);
            Assert.That(w.IsValid(ab), Is.False);
            Assert.That(w.IsValid(bc), Is.False);
            Assert.That(w.IsValid(ca), Is.True);
            Assert.That(w.JointCount, Is.EqualTo(1));
            w.Step(1f / 60f);
        }

        [Test]
        public void Joint_definition_defaults_are_as_documented()
        {
            JointDef d = JointDef.Default;
            Assert.That(d.Kind, Is.EqualTo(JointKind.Ball));
            Assert.That(d.AxisA, Is.EqualTo(Vector3.UnitX));
            Assert.That(d.LowerDeg, Is.EqualTo(float.NegativeInfinity));
            Assert.That(d.UpperDeg, Is.EqualTo(float.PositiveInfinity));
            Assert.That(d.MinLength, Is.EqualTo(-1f));
            Assert.That(d.MaxLength, Is.EqualTo(-1f));
            Assert.That(d.ConeDeg, Is.EqualTo(180f));
            Assert.That(d.TwistDeg, Is.EqualTo(180f));
            Assert.That(d.BreakForce, Is.EqualTo(float.PositiveInfinity));
            Assert.That(d.BreakTorque, Is.EqualTo(float.PositiveInfinity));
            Assert.That(d.CollideConnected, Is.False);
        }

        [Test]
        public void Jointed_bodies_do_not_collide_unless_asked()
        {
            var (w, a, b) = TwoBodies();
            w.CreateJoint(JointDef.Ball(a, b, Vector3.Zero, Vector3.Zero));
            Assert.That(w.JointBlocksCollision(a.Index, b.Index), Is.True);
            Assert.That(w.JointBlocksCollision(b.Index, a.Index), Is.True);
            var (w2, c, d) = TwoBodies();
            JointDef def = JointDef.Ball(c, d, Vector3.Zero, Vector3.Zero);
            def.CollideConnected = true;
            w2.CreateJoint(def);
            Assert.That(w2.JointBlocksCollision(c.Index, d.Index), Is.False);
        }
    }
}
