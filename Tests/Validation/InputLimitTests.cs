using System;
using System.Numerics;
using NUnit.Framework;

namespace Fulcrum.Tests.Validation
{
    /// <summary>
    /// Finite inputs that would overflow downstream are refused up front with the field named,
    /// and each refused call leaves the world exactly as it was (issue 11, item 4).
    /// </summary>
    public class InputLimitTests
    {
        static BodyHandle Ball(World world, Vector3 at, float radius = 0.5f)
        {
            BodyHandle b = world.CreateBody(BodyDef.Dynamic(at));
            world.AddShape(b, ShapeDef.Of(ShapeGeometry.Sphere(radius)));
            return b;
        }

        static int ShapeCount(World w, BodyHandle b) => w.GetShapes(b, Span<ShapeHandle>.Empty);

        [Test]
        public void A_huge_box_is_refused_before_the_body_changes()
        {
            var w = new World();
            BodyHandle b = Ball(w, Vector3.Zero);
            float mass = w.GetBody(b).Mass;
            Assert.That(() => w.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(new Vector3(1e13f)))),
                Throws.ArgumentException.With.Message.Contains("Limits.MaxShapeSize"));
            Assert.That(w.GetBody(b).Mass, Is.EqualTo(mass));
            Assert.That(ShapeCount(w, b), Is.EqualTo(1));
        }

        [Test]
        public void A_shape_whose_mass_leaves_the_range_is_refused_before_the_body_changes()
        {
            var w = new World();
            BodyHandle b = Ball(w, Vector3.Zero);
            float mass = w.GetBody(b).Mass;
            ShapeDef big = ShapeDef.Of(ShapeGeometry.Box(new Vector3(1e4f)));
            big.Density = 1e4f; // 8e16 kg
            Assert.That(() => w.AddShape(b, big), Throws.ArgumentException.With.Message.Contains("shape.Density"));
            Assert.That(w.GetBody(b).Mass, Is.EqualTo(mass));
            Assert.That(ShapeCount(w, b), Is.EqualTo(1));
        }

        [Test]
        public void Values_that_overflow_downstream_are_refused_with_the_field_named()
        {
            var w = new World();
            BodyHandle b = Ball(w, Vector3.Zero);
            Assert.That(() => w.GetBody(b).AngularVelocity = new Vector3(3e38f), Throws.ArgumentException.With.Message.Contains("AngularVelocity"));
            Assert.That(() => w.GetBody(b).LinearVelocity = new Vector3(3e38f, 0, 0), Throws.ArgumentException.With.Message.Contains("LinearVelocity"));
            Assert.That(() => w.AddTorque(b, new Vector3(3e38f)), Throws.ArgumentException.With.Message.Contains("torque"));
            Assert.That(() => w.AddForce(b, new Vector3(0, 3e38f, 0)), Throws.ArgumentException.With.Message.Contains("force"));
            BodyDef tiny = BodyDef.Dynamic(Vector3.Zero);
            tiny.Mass = 1e-38f;
            Assert.That(() => w.CreateBody(tiny), Throws.ArgumentException.With.Message.Contains("body.Mass"));
            Assert.That(() => w.SetMassProperties(b, new MassProperties(1e-38f, Vector3.Zero, Fulcrum.Mathematics.Mat3.Identity)),
                Throws.ArgumentException.With.Message.Contains("mass.Mass"));
            BodyDef far = BodyDef.Dynamic(new Vector3(0, 3e38f, 0));
            Assert.That(() => w.CreateBody(far), Throws.ArgumentException.With.Message.Contains("body.Position"));
            Assert.That(w.BodyCount, Is.EqualTo(1));
            Assert.That(w.GetBody(b).AngularVelocity, Is.EqualTo(Vector3.Zero));
            Assert.That(w.GetBody(b).Torque, Is.EqualTo(Vector3.Zero));
            Assert.That(w.GetBody(b).Force, Is.EqualTo(Vector3.Zero));
        }

        [Test]
        public void Forces_accumulating_past_the_limit_are_refused_and_the_sum_kept()
        {
            var w = new World();
            BodyHandle b = Ball(w, Vector3.Zero);
            w.AddForce(b, new Vector3(0, 0.9e20f, 0));
            Assert.That(() => w.AddForce(b, new Vector3(0, 0.9e20f, 0)), Throws.ArgumentException.With.Message.Contains("accumulated this step"));
            Assert.That(w.GetBody(b).Force.Y, Is.EqualTo(0.9e20f));
        }

        [Test]
        public void A_teleport_beyond_the_world_bounds_is_refused_and_the_jointed_partner_stays()
        {
            var w = new World(WorldSettings.Default.With((ref WorldSettings s) => s.Gravity = Vector3.Zero));
            BodyHandle a = Ball(w, Vector3.Zero);
            BodyHandle c = Ball(w, new Vector3(2, 0, 0));
            w.CreateJoint(JointDef.Ball(a, c, new Vector3(1, 0, 0), new Vector3(-1, 0, 0)));
            Assert.That(() => w.GetBody(a).Position = new Vector3(3e38f, 0, 0), Throws.ArgumentException.With.Message.Contains("Limits.MaxPosition"));
            for (int i = 0; i < 10; i++) w.Step(1 / 60f);
            Assert.That(w.GetBody(a).Position.Length(), Is.LessThan(1e-3f));
            Assert.That(Vector3.Distance(w.GetBody(c).Position, new Vector3(2, 0, 0)), Is.LessThan(1e-3f));
        }

        [Test]
        public void A_quaternion_of_huge_components_is_normalised_not_zeroed()
        {
            var w = new World();
            BodyHandle b = Ball(w, Vector3.Zero);
            w.GetBody(b).Rotation = new Quaternion(1e20f, 1e20f, 1e20f, 1e20f);
            Quaternion q = w.GetBody(b).Rotation;
            Assert.That(q.Length(), Is.EqualTo(1f).Within(1e-5f));
            Assert.That(q.W, Is.EqualTo(0.5f).Within(1e-5f));
            w.GetBody(b).AngularVelocity = new Vector3(1, 2, 3);
            for (int i = 0; i < 10; i++) w.Step(1 / 60f);
            Assert.That(Fulcrum.Mathematics.Validate.IsFinite(w.GetBody(b).Rotation), Is.True);
        }

        [Test]
        public void Time_step_substeps_iterations_and_threads_are_capped()
        {
            var w = new World();
            Assert.That(() => w.Step(1e6f), Throws.ArgumentException.With.Message.Contains("Limits.MinTimeStep/MaxTimeStep"));
            Assert.That(() => w.Step(1e-30f), Throws.ArgumentException.With.Message.Contains("dt"));
            Assert.That(() => new World(WorldSettings.Default.With((ref WorldSettings s) => s.Substeps = 1_000_000_000)), Throws.ArgumentException.With.Message.Contains("settings.Substeps"));
            Assert.That(() => new World(WorldSettings.Default.With((ref WorldSettings s) => s.Iterations = 1_000_000_000)), Throws.ArgumentException.With.Message.Contains("settings.Iterations"));
            Assert.That(() => new World(WorldSettings.Default.With((ref WorldSettings s) => s.Threads = 100_000)), Throws.ArgumentException.With.Message.Contains("settings.Threads"));
            Assert.That(() => w.Settings = WorldSettings.Default.With((ref WorldSettings s) => s.Substeps = Limits.MaxSubsteps + 1), Throws.ArgumentException);
            Assert.That(w.Settings.Substeps, Is.EqualTo(WorldSettings.Default.Substeps));
            Assert.That(() => new World(WorldSettings.Default.With((ref WorldSettings s) => { s.Substeps = Limits.MaxSubsteps; s.Threads = Limits.MaxThreads; })), Throws.Nothing);
        }

        [Test]
        public void A_velocity_above_the_cap_is_clamped_to_the_cap_not_zeroed()
        {
            var w = new World(WorldSettings.Default.With((ref WorldSettings s) => s.Gravity = Vector3.Zero));
            BodyHandle b = Ball(w, Vector3.Zero);
            w.GetBody(b).LinearVelocity = new Vector3(Limits.MaxInputSpeed, 0, 0);
            w.Step(1 / 60f);
            Assert.That(w.GetBody(b).LinearVelocity.X, Is.EqualTo(400f).Within(1e-3f));
            // The overflow case of the old clamp: the square of 3e38 is infinite.
            Vector3 v = new Vector3(3e38f, 3e38f, 0), spin = Vector3.Zero;
            Fulcrum.Dynamics.Integrator.ClampSpeed(400f, 0.5f, ref v, ref spin);
            Assert.That(v.Length(), Is.EqualTo(400f).Within(1e-2f));
            Assert.That(v.X, Is.EqualTo(v.Y));
        }

        [Test]
        public void Spin_cannot_fling_a_point_past_the_speed_cap()
        {
            var w = new World();
            BodyHandle ground = w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            w.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(50, 0.5f, 50))));
            BodyHandle box = w.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.49f, 0)));
            w.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            w.GetBody(box).AngularVelocity = new Vector3(0, 0, 1e6f);
            float radius = MathF.Sqrt(3) * 0.5f;
            float worst = 0;
            for (int i = 0; i < 120; i++)
            {
                w.Step(1 / 60f);
                var r = w.GetBody(box);
                worst = MathF.Max(worst, r.LinearVelocity.Length() + r.AngularVelocity.Length() * radius);
            }
            TestContext.Out.WriteLine($"worst point speed {worst} m/s (before the spin cap: 381,294 m/s)");
            // The integrator's bound; contact impulses in the step may add what the solver's
            // own velocity limits allow, which stays far below the 1e6 rad/s x 0.87 m input.
            Assert.That(worst, Is.LessThanOrEqualTo(400f * 1.05f));
            Assert.That(w.GetBody(box).AngularVelocity.Length(), Is.LessThanOrEqualTo(400f / radius * 1.001f));
        }

        [Test]
        public void Joint_inputs_that_overflow_are_refused_and_no_joint_is_made()
        {
            var w = new World();
            BodyHandle a = Ball(w, Vector3.Zero);
            BodyHandle c = Ball(w, new Vector3(2, 0, 0));
            Assert.That(() => w.CreateJoint(JointDef.Ball(a, c, new Vector3(3e38f, 0, 0), Vector3.Zero)), Throws.ArgumentException.With.Message.Contains("joint.AnchorA"));
            JointDef hinge = JointDef.Hinge(a, c, Vector3.Zero, Vector3.Zero, new Vector3(1e20f, 1e20f, 1e20f), Vector3.UnitX);
            Assert.That(() => w.CreateJoint(hinge), Throws.ArgumentException.With.Message.Contains("joint.AxisA"));
            JointDef motor = JointDef.Hinge(a, c, Vector3.Zero, Vector3.Zero, Vector3.UnitX, Vector3.UnitX);
            motor.MotorSpeed = 3e38f;
            motor.MaxMotorTorque = 10;
            Assert.That(() => w.CreateJoint(motor), Throws.ArgumentException.With.Message.Contains("joint.MotorSpeed"));
            Assert.That(w.JointCount, Is.EqualTo(0));
        }

        [Test]
        public void A_static_body_whose_shapes_weigh_too_much_stays_static()
        {
            var w = new World();
            BodyHandle slab = w.CreateBody(BodyDef.Static(Vector3.Zero));
            ShapeDef dense = ShapeDef.Of(ShapeGeometry.Box(new Vector3(1e4f)));
            dense.Density = 1e6f; // 8e18 kg: fine while static
            w.AddShape(slab, dense);
            Assert.That(() => w.SetBodyType(slab, BodyType.Dynamic), Throws.ArgumentException.With.Message.Contains("Limits.MinMass/MaxMass"));
            Assert.That(w.GetBody(slab).Type, Is.EqualTo(BodyType.Static));
            Assert.That(w.GetBody(slab).Mass, Is.EqualTo(0f));
            Assert.That(() => w.Reserve(int.MaxValue, 0), Throws.ArgumentException.With.Message.Contains("Limits.MaxReserve"));
        }

        [Test]
        public void A_shape_lighter_than_the_minimum_mass_is_refused_even_beside_a_heavy_one()
        {
            var w = new World();
            BodyHandle b = Ball(w, Vector3.Zero);
            ShapeDef feather = ShapeDef.Of(ShapeGeometry.Sphere(0.01f));
            feather.Density = 1e-30f; // 4e-36 kg: 1/m overflows once the ball is removed
            Assert.That(() => w.AddShape(b, feather), Throws.ArgumentException.With.Message.Contains("this shape's mass"));
            Assert.That(ShapeCount(w, b), Is.EqualTo(1));
        }
    }
}
