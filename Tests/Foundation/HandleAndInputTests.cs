using System;
using System.Numerics;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    public class HandleAndInputTests
    {
        static BodyHandle Ball(World world, Vector3 at)
        {
            BodyHandle b = world.CreateBody(BodyDef.Dynamic(at));
            world.AddShape(b, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            return b;
        }

        [Test]
        public void Destroyed_body_handle_is_stale_everywhere()
        {
            var world = new World();
            BodyHandle a = Ball(world, Vector3.Zero);
            world.DestroyBody(a);
            Assert.That(world.IsValid(a), Is.False);
            Assert.That(() => world.GetBody(a), Throws.TypeOf<StaleHandleException>());
            Assert.That(() => world.DestroyBody(a), Throws.TypeOf<StaleHandleException>());
            Assert.That(() => world.AddForce(a, Vector3.One), Throws.TypeOf<StaleHandleException>());
            Assert.That(() => world.AddShape(a, ShapeDef.Of(ShapeGeometry.Sphere(1))), Throws.TypeOf<StaleHandleException>());
        }

        [Test]
        public void Reused_slot_does_not_answer_to_the_old_handle()
        {
            var world = new World();
            BodyHandle a = Ball(world, Vector3.Zero);
            world.DestroyBody(a);
            BodyHandle b = Ball(world, new Vector3(5, 0, 0));
            Assert.That(b.Index, Is.EqualTo(a.Index), "the slot is reused");
            Assert.That(b.Generation, Is.Not.EqualTo(a.Generation));
            Assert.That(() => world.GetBody(a), Throws.TypeOf<StaleHandleException>());
            Assert.That(world.GetBody(b).Position.X, Is.EqualTo(5f));
        }

        [Test]
        public void None_handle_and_foreign_handle_are_rejected()
        {
            var world = new World();
            Assert.That(() => world.GetBody(BodyHandle.None), Throws.TypeOf<StaleHandleException>());
            Assert.That(() => world.GetBody(new BodyHandle(3, 1)), Throws.TypeOf<StaleHandleException>());
            Assert.That(() => world.RemoveShape(new ShapeHandle(0, 1)), Throws.TypeOf<StaleHandleException>());
        }

        [Test]
        public void Destroying_a_body_removes_its_shapes()
        {
            var world = new World();
            BodyHandle a = world.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            ShapeHandle s = world.AddShape(a, ShapeDef.Of(ShapeGeometry.Box(Vector3.One)));
            world.DestroyBody(a);
            Assert.That(world.ShapeCount, Is.EqualTo(0));
            Assert.That(world.IsValid(s), Is.False);
        }

        [Test]
        public void Removing_a_shape_recomputes_the_mass()
        {
            var world = new World();
            BodyHandle a = world.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            world.AddShape(a, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            ShapeHandle s = world.AddShape(a, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            Assert.That(world.GetBody(a).Mass, Is.EqualTo(2000f).Within(1e-2f));
            world.RemoveShape(s);
            Assert.That(world.GetBody(a).Mass, Is.EqualTo(1000f).Within(1e-2f));
        }

        [Test]
        public void Non_finite_body_definition_is_rejected_and_nothing_is_created()
        {
            var world = new World();
            Ball(world, Vector3.Zero);
            BodyDef bad = BodyDef.Dynamic(new Vector3(float.NaN, 0, 0));
            Assert.That(() => world.CreateBody(bad), Throws.ArgumentException.With.Message.Contains("body.Position"));
            bad = BodyDef.Dynamic(Vector3.Zero);
            bad.LinearVelocity = new Vector3(0, float.PositiveInfinity, 0);
            Assert.That(() => world.CreateBody(bad), Throws.ArgumentException.With.Message.Contains("body.LinearVelocity"));
            bad = BodyDef.Dynamic(Vector3.Zero);
            bad.Rotation = new Quaternion(0, 0, 0, 0);
            Assert.That(() => world.CreateBody(bad), Throws.ArgumentException.With.Message.Contains("body.Rotation"));
            bad = BodyDef.Dynamic(Vector3.Zero);
            bad.Mass = -2;
            Assert.That(() => world.CreateBody(bad), Throws.ArgumentException.With.Message.Contains("body.Mass"));
            Assert.That(world.BodyCount, Is.EqualTo(1));
        }

        [Test]
        public void Zero_or_negative_sizes_are_rejected_naming_the_field()
        {
            Assert.That(() => ShapeGeometry.Sphere(0), Throws.ArgumentException.With.Message.Contains("sphere.radius"));
            Assert.That(() => ShapeGeometry.Sphere(-1), Throws.ArgumentException.With.Message.Contains("sphere.radius"));
            Assert.That(() => ShapeGeometry.Box(new Vector3(1, 0, 1)), Throws.ArgumentException.With.Message.Contains("box.halfExtents"));
            Assert.That(() => ShapeGeometry.Capsule(0.5f, -1), Throws.ArgumentException.With.Message.Contains("capsule.halfHeight"));
            Assert.That(() => ShapeGeometry.Plane(Vector3.Zero, 0), Throws.ArgumentException.With.Message.Contains("plane.normal"));
            Assert.That(() => ShapeGeometry.Box(new Vector3(float.NaN, 1, 1)), Throws.ArgumentException);
        }

        [Test]
        public void Unset_geometry_and_bad_material_values_are_rejected_and_the_body_keeps_its_mass()
        {
            var world = new World();
            BodyHandle a = Ball(world, Vector3.Zero);
            float mass = world.GetBody(a).Mass;
            Assert.That(() => world.AddShape(a, ShapeDef.Default), Throws.ArgumentException.With.Message.Contains("Geometry"));
            ShapeDef s = ShapeDef.Of(ShapeGeometry.Sphere(1));
            s.Friction = -0.1f;
            Assert.That(() => world.AddShape(a, s), Throws.ArgumentException.With.Message.Contains("Friction"));
            s = ShapeDef.Of(ShapeGeometry.Sphere(1));
            s.Restitution = 1.5f;
            Assert.That(() => world.AddShape(a, s), Throws.ArgumentException.With.Message.Contains("Restitution"));
            Assert.That(world.ShapeCount, Is.EqualTo(1));
            Assert.That(world.GetBody(a).Mass, Is.EqualTo(mass));
        }

        [Test]
        public void Planes_only_go_on_static_bodies()
        {
            var world = new World();
            BodyHandle a = world.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            Assert.That(() => world.AddShape(a, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0))), Throws.ArgumentException.With.Message.Contains("static"));
            Assert.That(world.ShapeCount, Is.EqualTo(0));
        }

        [Test]
        public void Non_finite_force_is_rejected_and_the_velocity_is_untouched()
        {
            var world = new World();
            BodyHandle a = Ball(world, Vector3.Zero);
            Assert.That(() => world.AddForce(a, new Vector3(float.NaN, 0, 0), ForceMode.Impulse), Throws.ArgumentException);
            Assert.That(() => world.AddTorque(a, new Vector3(0, float.NegativeInfinity, 0)), Throws.ArgumentException);
            Assert.That(() => world.GetBody(a).LinearVelocity = new Vector3(float.NaN, 0, 0), Throws.ArgumentException);
            Assert.That(world.GetBody(a).LinearVelocity, Is.EqualTo(Vector3.Zero));
            Assert.That(world.GetBody(a).Force, Is.EqualTo(Vector3.Zero));
        }

        [Test]
        public void Bad_step_and_bad_settings_are_rejected_and_the_world_is_unchanged()
        {
            var world = new World();
            BodyHandle a = Ball(world, new Vector3(0, 3, 0));
            Assert.That(() => world.Step(0), Throws.ArgumentException);
            Assert.That(() => world.Step(float.NaN), Throws.ArgumentException);
            Assert.That(() => world.Step(-1f / 60f), Throws.ArgumentException);
            Assert.That(world.StepIndex, Is.EqualTo(0));
            Assert.That(world.GetBody(a).Position.Y, Is.EqualTo(3f));

            WorldSettings s = world.Settings;
            s.Iterations = 0;
            Assert.That(() => world.Settings = s, Throws.ArgumentException.With.Message.Contains("Iterations"));
            s = world.Settings;
            s.Substeps = -1;
            Assert.That(() => world.Settings = s, Throws.ArgumentException.With.Message.Contains("Substeps"));
            Assert.That(world.Settings.Iterations, Is.EqualTo(WorldSettings.Default.Iterations));
            Assert.That(() => new World(s), Throws.ArgumentException);
        }

        [Test]
        public void Bad_mass_properties_are_rejected()
        {
            var world = new World();
            BodyHandle a = Ball(world, Vector3.Zero);
            Assert.That(() => world.SetMassProperties(a, new MassProperties(-1, Vector3.Zero, Mat3.Identity)), Throws.ArgumentException.With.Message.Contains("Mass"));
            Assert.That(() => world.SetMassProperties(a, new MassProperties(0, Vector3.Zero, Mat3.Identity)), Throws.ArgumentException);
            Assert.That(() => world.SetMassProperties(a, new MassProperties(1, Vector3.Zero, Mat3.Identity * -1)), Throws.ArgumentException.With.Message.Contains("Inertia"));
            world.SetMassProperties(a, new MassProperties(3, Vector3.Zero, Mat3.Identity));
            Assert.That(world.GetBody(a).Mass, Is.EqualTo(3f));
            world.ResetMassProperties(a);
            Assert.That(world.GetBody(a).Mass, Is.EqualTo(MassProperties.Sphere(0.5f, 1000).Mass).Within(1e-3f));
        }

        [Test]
        public void Kinematic_target_on_a_dynamic_body_is_refused()
        {
            var world = new World();
            BodyHandle a = Ball(world, Vector3.Zero);
            Assert.That(() => world.SetKinematicTarget(a, Vector3.One, Quaternion.Identity), Throws.InvalidOperationException.With.Message.Contains("kinematic"));
        }
    }
}
