using System;
using System.Numerics;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class ContinuousCollisionTests
    {
        const float Dt = 1 / 60f;

        static World NoGravity()
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            s.EnableSleeping = false;
            return new World(s);
        }

        static BodyHandle Bullet(World w, Vector3 at, Vector3 velocity, bool ccd, ShapeGeometry shape)
        {
            BodyDef d = BodyDef.Dynamic(at);
            d.Ccd = ccd;
            d.LinearVelocity = velocity;
            BodyHandle b = w.CreateBody(d);
            w.AddShape(b, ShapeDef.Of(shape));
            return b;
        }

        static void Wall(World w, Vector3 at, Vector3 half) =>
            w.AddShape(w.CreateBody(BodyDef.Static(at)), ShapeDef.Of(ShapeGeometry.Box(half)));

        [TestCase(true)]
        [TestCase(false)]
        public void A_5cm_sphere_at_300_mps_never_passes_a_2cm_static_wall(bool wallOnBulletsLayer)
        {
            var w = NoGravity();
            ShapeDef wall = ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.01f, 2, 2)));
            // The control: a wall on a layer the bullet ignores must be passed, or the test could not fail.
            wall.Layer = wallOnBulletsLayer ? 0 : 5;
            w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(3, 0, 0))), wall);
            BodyDef d = BodyDef.Dynamic(Vector3.Zero);
            d.Ccd = true;
            d.LinearVelocity = new Vector3(300, 0, 0);
            BodyHandle ball = w.CreateBody(d);
            ShapeDef bullet = ShapeDef.Of(ShapeGeometry.Sphere(0.025f));
            bullet.CollidesWith = ~(1u << 5);
            w.AddShape(ball, bullet);
            float maxX = float.MinValue;
            for (int i = 0; i < 60; i++)
            {
                w.Step(Dt);
                maxX = MathF.Max(maxX, w.GetBody(ball).Position.X);
            }
            float slop = w.Settings.LinearSlop;
            if (wallOnBulletsLayer)
            {
                // At most a slop into the wall's face (a solver may let it rest there).
                Assert.That(maxX, Is.LessThanOrEqualTo(3 - 0.01f - 0.025f + slop));
                // Stopped within a few slops of the wall, not far in front of it.
                Assert.That(maxX, Is.GreaterThan(3 - 0.01f - 0.025f - 0.02f));
            }
            else Assert.That(maxX, Is.GreaterThan(3), "an ignored wall is passed: the check above can fail");
        }

        [Test]
        public void Sphere_bullets_from_many_directions_never_pass_the_wall()
        {
            var r = new Random(3);
            for (int n = 0; n < 40; n++)
            {
                var w = NoGravity();
                Wall(w, Vector3.Zero, new Vector3(0.01f, 3, 3));
                Vector3 dir = Vector3.Normalize(new Vector3(1, (float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f));
                BodyHandle ball = Bullet(w, -dir * 2, dir * 300, true, ShapeGeometry.Sphere(0.025f));
                for (int i = 0; i < 10; i++)
                {
                    w.Step(Dt);
                    Assert.That(w.GetBody(ball).Position.X, Is.LessThan(-0.01f - 0.025f + w.Settings.LinearSlop + 1e-4f), $"shot {n} step {i}");
                }
            }
        }

        [Test]
        public void A_thin_fast_spinning_box_never_passes_a_thin_floor()
        {
            var s = WorldSettings.Default;
            s.EnableSleeping = false;
            var w = new World(s);
            Wall(w, new Vector3(0, -0.01f, 0), new Vector3(5, 0.01f, 5));
            BodyDef d = BodyDef.Dynamic(new Vector3(0, 3, 0));
            d.Ccd = true;
            d.LinearVelocity = new Vector3(0.5f, -120, 0);
            d.AngularVelocity = new Vector3(0, 0, 20);
            BodyHandle plate = w.CreateBody(d);
            w.AddShape(plate, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f, 0.01f, 0.5f))));
            for (int i = 0; i < 60; i++)
            {
                w.Step(Dt);
                Aabb box = w.GetShapeAabb(FirstShape(w, plate));
                Pose pose = w.GetBody(plate).Pose;
                // The lowest corner of the plate stays above the floor's top (y = 0).
                float lowest = float.MaxValue;
                for (int c = 0; c < 8; c++)
                {
                    var corner = new Vector3((c & 1) != 0 ? 0.5f : -0.5f, (c & 2) != 0 ? 0.01f : -0.01f, (c & 4) != 0 ? 0.5f : -0.5f);
                    lowest = MathF.Min(lowest, pose.TransformPoint(corner).Y);
                }
                // Resting contact may sink up to a slop or two once a solver holds it up.
                Assert.That(lowest, Is.GreaterThan(-2 * w.Settings.LinearSlop), $"step {i}");
            }
        }

        [Test]
        public void Bullets_stop_at_a_plane_and_at_a_mesh_wall()
        {
            var w = NoGravity();
            w.AddShape(w.CreateBody(BodyDef.Static(Vector3.Zero)), ShapeDef.Of(ShapeGeometry.Plane(-Vector3.UnitX, -5)));   // solid for x >= 5
            var mesh = TriangleMesh.Create(new[] { new Vector3(2, -2, -2), new Vector3(2, 2, -2), new Vector3(2, 2, 2), new Vector3(2, -2, 2) }, new[] { 0, 2, 1, 0, 3, 2 });
            Assert.That(mesh.Normals[0].X, Is.LessThan(0), "the mesh wall faces the bullet");
            w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, 0, 10))), ShapeDef.Of(ShapeGeometry.TriangleMesh(mesh)));
            BodyHandle a = Bullet(w, Vector3.Zero, new Vector3(300, 0, 0), true, ShapeGeometry.Sphere(0.025f));
            BodyHandle b = Bullet(w, new Vector3(0, 0, 10), new Vector3(300, 0, 0), true, ShapeGeometry.Box(new Vector3(0.02f)));
            for (int i = 0; i < 20; i++)
            {
                w.Step(Dt);
                float slop = w.Settings.LinearSlop;
                Assert.That(w.GetBody(a).Position.X, Is.LessThan(5 - 0.025f + slop + 1e-4f));
                Assert.That(w.GetBody(b).Position.X, Is.LessThan(2 - 0.02f + slop + 1e-4f));
            }
        }

        [Test]
        public void A_fast_ccd_body_sliding_along_a_floor_is_not_held_back()
        {
            var w = NoGravity();
            // Frictionless, so that a solver's push out of the 2 mm overlap cannot slow it either.
            ShapeDef floor = ShapeDef.Of(ShapeGeometry.Box(new Vector3(100, 0.5f, 5)));
            floor.Friction = 0;
            w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0))), floor);
            BodyDef d = BodyDef.Dynamic(new Vector3(-50, 0.1f - 0.002f, 0));
            d.Ccd = true;
            d.LinearVelocity = new Vector3(120, 0, 0);
            BodyHandle b = w.CreateBody(d);
            ShapeDef ball = ShapeDef.Of(ShapeGeometry.Sphere(0.1f));
            ball.Friction = 0;
            w.AddShape(b, ball);
            w.Step(Dt);
            Assert.That(w.GetBody(b).Position.X, Is.EqualTo(-48f).Within(1e-3f));
        }

        [Test]
        public void Ccd_counts_shapes_of_bodies_that_ask_so_the_stage_can_skip()
        {
            var w = NoGravity();
            BodyHandle b = Bullet(w, Vector3.Zero, Vector3.Zero, false, ShapeGeometry.Sphere(0.1f));
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.1f))));
            Assert.That(w.CcdShapeCount, Is.EqualTo(0));
            var body = w.GetBody(b);
            body.Ccd = true;
            Assert.That(w.CcdShapeCount, Is.EqualTo(2));
            BodyHandle c = Bullet(w, Vector3.One, Vector3.Zero, true, ShapeGeometry.Sphere(0.1f));
            Assert.That(w.CcdShapeCount, Is.EqualTo(3));
            w.DestroyBody(b);
            Assert.That(w.CcdShapeCount, Is.EqualTo(1));
            w.GetBody(c).Ccd = false;
            Assert.That(w.CcdShapeCount, Is.EqualTo(0));
        }

        static ShapeHandle FirstShape(World w, BodyHandle b)
        {
            Span<ShapeHandle> s = stackalloc ShapeHandle[1];
            w.GetShapes(b, s);
            return s[0];
        }
    }
}
