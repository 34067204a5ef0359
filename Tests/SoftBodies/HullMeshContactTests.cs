using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.Foundation;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class HullMeshContactTests
    {
        static readonly NeoHookeanMaterial Jelly = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, 0.4f, 1000f);

        /// <summary>The 8 corners of a box of the given half-extents.</summary>
        static Vector3[] BoxCorners(Vector3 half)
        {
            var corners = new Vector3[8];
            for (int i = 0; i < 8; i++)
                corners[i] = new Vector3((i & 1) == 0 ? -half.X : half.X, (i & 2) == 0 ? -half.Y : half.Y, (i & 4) == 0 ? -half.Z : half.Z);
            return corners;
        }

        /// <summary>A flat square of 2 n^2 triangles facing +y at height 0, <paramref name="size"/> metres across.</summary>
        static TriangleMesh FloorMesh(float size, int n)
        {
            var v = new Vector3[(n + 1) * (n + 1)];
            for (int j = 0; j <= n; j++)
                for (int i = 0; i <= n; i++)
                    v[j * (n + 1) + i] = new Vector3(-0.5f * size + size * i / n, 0, -0.5f * size + size * j / n);
            var t = new int[6 * n * n];
            int k = 0;
            for (int j = 0; j < n; j++)
                for (int i = 0; i < n; i++)
                {
                    int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                    // (c - a) x (b - a) ... wound so (b - a) x (c - a) points up.
                    t[k++] = a; t[k++] = c; t[k++] = b;
                    t[k++] = b; t[k++] = c; t[k++] = d;
                }
            return TriangleMesh.Create(v, t);
        }

        static World WorldWithFloor(string kind, float friction = 0.5f)
        {
            var world = new World();
            var half = new Vector3(1f, 0.25f, 1f);
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, kind == "mesh" || kind == "plane" ? 0 : -half.Y, 0)));
            ShapeGeometry geometry = kind switch
            {
                "box" => ShapeGeometry.Box(half),
                "hull" => ShapeGeometry.ConvexHull(BoxCorners(half)),
                "mesh" => ShapeGeometry.TriangleMesh(FloorMesh(2f, 4)),
                _ => ShapeGeometry.Plane(Vector3.UnitY, 0f),
            };
            world.AddShape(ground, ShapeDef.Of(geometry).With((ref ShapeDef s) => s.Friction = friction));
            return world;
        }

        static float LowestY(SoftBody body)
        {
            float min = float.MaxValue;
            foreach (Vector3 p in body.Positions) min = MathF.Min(min, p.Y);
            return min;
        }

        static (float lowest, float centre) Settle(World world)
        {
            SoftBody jelly = world.GetSoftBody(world.CreateSoftBody(SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(0.1f, 0.25f, -0.05f))));
            SoftBodyScenes.Run(world, 90);
            return (LowestY(jelly), jelly.ComputeStats().Centroid.Y);
        }

        [Test]
        public void Jelly_rests_at_the_same_height_on_a_hull_box_a_mesh_floor_and_a_box()
        {
            var box = Settle(WorldWithFloor("box"));
            var hull = Settle(WorldWithFloor("hull"));
            var mesh = Settle(WorldWithFloor("mesh"));
            var plane = Settle(WorldWithFloor("plane"));
            TestContext.Out.WriteLine($"lowest vertex / centroid: box {box.lowest:F5}/{box.centre:F5}, hull {hull.lowest:F5}/{hull.centre:F5}, mesh {mesh.lowest:F5}/{mesh.centre:F5}, plane {plane.lowest:F5}/{plane.centre:F5}");
            Assert.That(box.lowest, Is.EqualTo(0.005f).Within(0.001f), "vertices keep the collision radius from the box top");
            Assert.That(hull.lowest, Is.EqualTo(box.lowest).Within(0.001f));
            Assert.That(hull.centre, Is.EqualTo(box.centre).Within(0.001f));
            Assert.That(mesh.lowest, Is.EqualTo(box.lowest).Within(0.001f));
            Assert.That(mesh.centre, Is.EqualTo(box.centre).Within(0.001f));
            Assert.That(mesh.centre, Is.EqualTo(plane.centre).Within(0.001f));
        }

        [Test]
        public void A_rising_jelly_passes_up_through_the_back_of_a_one_sided_mesh_floor()
        {
            World world = WorldWithFloor("mesh");
            world.Gravity = Vector3.Zero;
            var def = SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(0, -0.4f, 0));
            def.LinearVelocity = new Vector3(0, 2f, 0);
            SoftBody jelly = world.GetSoftBody(world.CreateSoftBody(def));
            SoftBodyScenes.Run(world, 30);
            TestContext.Out.WriteLine($"centroid {jelly.ComputeStats().Centroid.Y:F4}, lowest {LowestY(jelly):F4}");
            Assert.That(LowestY(jelly), Is.GreaterThan(0.2f), "came through from the back side and kept going");
            Assert.That(jelly.ComputeStats().Centroid.Y, Is.EqualTo(0.6f).Within(0.02f), "unhindered: 0.5 s at 2 m/s from -0.4");
        }

        [Test]
        public void A_falling_jelly_does_not_pass_down_through_a_mesh_floor()
        {
            World world = WorldWithFloor("mesh");
            var def = SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(0, 0.6f, 0));
            def.LinearVelocity = new Vector3(0, -4f, 0);
            SoftBody jelly = world.GetSoftBody(world.CreateSoftBody(def));
            float lowest = float.MaxValue;
            for (int i = 0; i < 60; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                lowest = MathF.Min(lowest, LowestY(jelly));
            }
            TestContext.Out.WriteLine($"lowest vertex over the fall {lowest:F5}");
            Assert.That(lowest, Is.GreaterThan(-0.002f));
        }

        static float SlideOnSlope(float mu, bool hull, out float expected)
        {
            float angle = MathF.PI / 6f;
            var world = new World();
            Quaternion tilt = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, angle);
            var half = new Vector3(3f, 0.25f, 1f);
            // The slope's top face passes through the origin.
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Transform(new Vector3(0, -half.Y, 0), tilt)).With((ref BodyDef s) => s.Rotation = tilt));
            world.AddShape(ground, ShapeDef.Of(hull ? ShapeGeometry.ConvexHull(BoxCorners(half)) : ShapeGeometry.Box(half)).With((ref ShapeDef s) => s.Friction = mu));
            var def = SoftBodyScenes.Cube(0.2f, 2, Jelly, Vector3.Transform(new Vector3(0, 0.106f, 0), tilt));
            def.Rotation = tilt;
            def.Friction = mu;
            SoftBody jelly = world.GetSoftBody(world.CreateSoftBody(def));
            SoftBodyScenes.Run(world, 15);
            Vector3 downhill = Vector3.Transform(-Vector3.UnitX, tilt);
            float start = Vector3.Dot(jelly.ComputeStats().Centroid, downhill);
            SoftBodyScenes.Run(world, 30);
            float travelled = Vector3.Dot(jelly.ComputeStats().Centroid, downhill) - start;
            // A rigid block from rest at t = 0 slides with a = g (sin - mu cos); from t = 0.25 s
            // to 0.75 s it covers a (0.75^2 - 0.25^2) / 2 = 0.25 a.
            expected = 0.25f * MathF.Max(0f, 9.81f * (MathF.Sin(angle) - mu * MathF.Cos(angle)));
            return travelled;
        }

        [Test]
        public void Jelly_on_a_30deg_hull_slope_with_mu_0_8_stays_put()
        {
            float travelled = SlideOnSlope(0.8f, true, out _);
            float onBox = SlideOnSlope(0.8f, false, out _);
            TestContext.Out.WriteLine($"travelled {travelled:F4} m in 0.5 s (on a box slope {onBox:F4} m)");
            // 1.0 mm measured (it crept 2 cm before friction also ran after the elastic pass).
            Assert.That(travelled, Is.EqualTo(0f).Within(0.0025f), "a little shear, no creep");
            Assert.That(onBox, Is.EqualTo(travelled).Within(1e-4f), "the hull box behaves as the box");
        }

        [Test]
        public void Jelly_on_a_30deg_hull_slope_with_mu_0_2_slides_at_the_rigid_rate()
        {
            float travelled = SlideOnSlope(0.2f, true, out float rigid);
            TestContext.Out.WriteLine($"travelled {travelled:F4} m in 0.5 s; a rigid block {rigid:F4} m");
            Assert.That(travelled, Is.EqualTo(rigid).Within(0.1f * rigid));
        }
        static (float height, float imbalance) BodyOnJelly(bool hull)
        {
            World world = SoftBodyScenes.WorldWithGround();
            var material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 5e4f, 0.45f, 1000f);
            SoftBody jelly = world.GetSoftBody(world.CreateSoftBody(SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.5f, 0.2f, 0.5f), 5, 2, 5), material, new Vector3(0, 0.105f, 0))));
            BodyHandle body = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.32f, 0)));
            var half = new Vector3(0.1f);
            world.AddShape(body, ShapeDef.Of(hull ? ShapeGeometry.ConvexHull(BoxCorners(half)) : ShapeGeometry.Box(half)).With((ref ShapeDef s) => s.Density = 2000f));
            float mass = world.GetBody(body).Mass;
            SoftBodyScenes.Run(world, 180);
            Vector3 before = jelly.ComputeStats().Momentum + mass * world.GetBody(body).LinearVelocity;
            SoftBodyScenes.Run(world, 30);
            Vector3 after = jelly.ComputeStats().Momentum + mass * world.GetBody(body).LinearVelocity;
            // Net force over the window against the weight: the ground and the jelly together carry it.
            float weight = (jelly.TotalMass + mass) * 9.81f;
            float imbalance = (after - before).Y / (30 * SoftBodyScenes.Dt) / weight;
            return (world.GetBody(body).Position.Y, imbalance);
        }

        [Test]
        public void A_dynamic_hull_box_rests_on_jelly_where_a_box_does_and_the_weight_is_carried()
        {
            var onHull = BodyOnJelly(hull: true);
            var onBox = BodyOnJelly(hull: false);
            TestContext.Out.WriteLine($"hull body at {onHull.height:F4} m (box {onBox.height:F4} m); net vertical force / weight over 0.5 s: hull {onHull.imbalance:P2}, box {onBox.imbalance:P2}");
            Assert.That(onHull.height, Is.InRange(0.26f, 0.315f), "held up by the jelly, which gives a little");
            Assert.That(onHull.height, Is.EqualTo(onBox.height).Within(0.001f));
            Assert.That(onHull.imbalance, Is.EqualTo(0f).Within(0.03f), "support equals weight within 3 %");
        }

        [Test]
        public void A_compound_of_a_box_and_a_hull_holds_jelly_level_across_both()
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, -0.25f, 0)));
            var half = new Vector3(0.5f, 0.25f, 1f);
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(half)).With((ref ShapeDef s) => s.LocalPose = new Fulcrum.Mathematics.Pose(new Vector3(-0.5f, 0, 0), Quaternion.Identity)));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.ConvexHull(BoxCorners(half))).With((ref ShapeDef s) => s.LocalPose = new Fulcrum.Mathematics.Pose(new Vector3(0.5f, 0, 0), Quaternion.Identity)));
            SoftBody jelly = world.GetSoftBody(world.CreateSoftBody(SoftBodyScenes.Cube(0.3f, 3, Jelly, new Vector3(0, 0.25f, 0))));
            SoftBodyScenes.Run(world, 90);
            float left = float.MaxValue, right = float.MaxValue;
            foreach (Vector3 p in jelly.Positions)
            {
                if (p.X < -0.1f) left = MathF.Min(left, p.Y);
                if (p.X > 0.1f) right = MathF.Min(right, p.Y);
            }
            TestContext.Out.WriteLine($"lowest vertex over the box {left:F5} m, over the hull {right:F5} m");
            Assert.That(left, Is.EqualTo(0.005f).Within(0.001f));
            Assert.That(right, Is.EqualTo(left).Within(0.0005f));
        }
    }
}
