using System;
using System.IO;
using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>World.IgnoreCollision and its component face PhysicsScene.IgnoreCollision (Unity's Physics.IgnoreCollision).</summary>
    public class IgnoreCollisionTests
    {
        const float Dt = 1f / 60f;

        static World Drop(out ShapeHandle ground, out ShapeHandle ball, out BodyHandle body)
        {
            var w = new World();
            BodyHandle g = w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            ground = w.AddShape(g, ShapeDef.Of(ShapeGeometry.Box(new Vector3(10, 0.5f, 10))));
            BodyDef d = BodyDef.Default;
            d.Position = new Vector3(0, 0.5f, 0);
            body = w.CreateBody(d);
            ball = w.AddShape(body, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            return w;
        }

        [Test]
        public void Ignored_shapes_pass_through_each_other_and_collide_again_when_the_setting_is_lifted()
        {
            World w = Drop(out ShapeHandle ground, out ShapeHandle ball, out BodyHandle body);
            for (int k = 0; k < 30; k++) w.Step(Dt);
            Assert.That(w.GetBody(body).Position.Y, Is.EqualTo(0.5f).Within(0.02f), "rests");
            w.IgnoreCollision(ground, ball);
            Assert.That(w.GetIgnoreCollision(ball, ground), Is.True, "either order");
            for (int k = 0; k < 12; k++) w.Step(Dt);
            float y = w.GetBody(body).Position.Y;
            Assert.That(y, Is.LessThan(0.3f), "sinks into the ground");
            w.IgnoreCollision(ground, ball, false);
            for (int k = 0; k < 90; k++) w.Step(Dt);
            Assert.That(w.GetBody(body).Position.Y, Is.GreaterThan(y), "the contact came back and pushes it out");
            Assert.That(w.GetBody(body).Position.Y, Is.EqualTo(0.5f).Within(0.05f));
            Assert.Throws<ArgumentException>(() => w.IgnoreCollision(ball, ball));
        }

        [Test]
        public void A_removed_shape_forgets_its_ignored_pairs_so_a_new_shape_in_its_slot_collides()
        {
            World w = Drop(out ShapeHandle ground, out ShapeHandle ball, out BodyHandle body);
            w.IgnoreCollision(ground, ball);
            w.RemoveShape(ball);
            ShapeHandle again = w.AddShape(body, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            Assert.That(again.Index, Is.EqualTo(ball.Index), "the slot is reused");
            Assert.That(w.GetIgnoreCollision(ground, again), Is.False);
            for (int k = 0; k < 60; k++) w.Step(Dt);
            Assert.That(w.GetBody(body).Position.Y, Is.EqualTo(0.5f).Within(0.02f));
        }

        [Test]
        public void Ignored_pairs_are_part_of_the_saved_state()
        {
            World a = Drop(out ShapeHandle ground, out ShapeHandle ball, out BodyHandle body);
            a.IgnoreCollision(ground, ball);
            for (int k = 0; k < 5; k++) a.Step(Dt);
            var state = new MemoryStream();
            a.SaveState(state);
            var b = new World();
            b.RestoreState(new MemoryStream(state.ToArray()));
            Assert.That(b.GetIgnoreCollision(new ShapeHandle(ground.Index, ground.Generation, b.Id), new ShapeHandle(ball.Index, ball.Generation, b.Id)), Is.True);
            for (int k = 0; k < 30; k++) { a.Step(Dt); b.Step(Dt); }
            Assert.That(b.Bodies.Position[body.Index], Is.EqualTo(a.Bodies.Position[body.Index]), "bit for bit");
            Assert.That(a.Bodies.Position[body.Index].Y, Is.LessThan(-0.5f), "and still falling through");
        }

        [Test]
        public void Component_ignore_survives_a_rebuild_and_is_forgotten_on_deactivation()
        {
            var scene = new PhysicsScene(WorldSettings.Default, Dt);
            Entity g = scene.CreateEntity("Ground", new Vector3(0, -0.5f, 0));
            var ground = g.AddComponent<BoxCollider>();
            ground.size = new Vector3(20, 1, 20);
            Entity e = scene.CreateEntity("Ball", new Vector3(0, 0.5f, 0));
            var rb = e.AddComponent<Rigidbody>();
            var sphere = e.AddComponent<SphereCollider>();
            scene.IgnoreCollision(sphere, ground);
            sphere.radius = 0.4f;                       // rebuilds the shape
            for (int k = 0; k < 30; k++) scene.Tick(Dt);
            Assert.That(rb.position.Y, Is.LessThan(-0.5f), "falls through the ground");
            Assert.That(scene.GetIgnoreCollision(ground, sphere), Is.True);

            rb.position = new Vector3(0, 0.4f, 0);
            rb.linearVelocity = Vector3.Zero;
            e.SetActive(false);
            e.SetActive(true);
            Assert.That(scene.GetIgnoreCollision(ground, sphere), Is.False, "deactivation forgets it, as in Unity");
            for (int k = 0; k < 30; k++) scene.Tick(Dt);
            Assert.That(rb.position.Y, Is.EqualTo(0.4f).Within(0.03f), "rests on the ground again");
        }
    }
}
