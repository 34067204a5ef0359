using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;
using NUnit.Framework;
using static Fulcrum.Tests.Collision.CollisionTestKit;

namespace Fulcrum.Tests.Collision
{
    public class QueryTests
    {
        static readonly Vector3[] CubeCorners = BuildCorners();

        static Vector3[] BuildCorners()
        {
            var c = new Vector3[8];
            for (int i = 0; i < 8; i++) c[i] = new Vector3((i & 1) != 0 ? 0.4f : -0.4f, (i & 2) != 0 ? 0.3f : -0.3f, (i & 4) != 0 ? 0.5f : -0.5f);
            return c;
        }

        // A world of mixed shapes: a ground plane, a mesh ramp, and 150 random bodies.
        static World MixedWorld(int seed, out List<ShapeHandle> shapes)
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            shapes = new List<ShapeHandle>();
            BodyHandle ground = w.CreateBody(BodyDef.Static(Vector3.Zero));
            shapes.Add(w.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, -5))));
            var mesh = TriangleMesh.Create(
                new[] { new Vector3(-8, -4, -8), new Vector3(8, -2, -8), new Vector3(8, -2, 8), new Vector3(-8, -4, 8) },
                new[] { 0, 3, 2, 0, 2, 1 });
            shapes.Add(w.AddShape(ground, ShapeDef.Of(ShapeGeometry.TriangleMesh(mesh))));
            var hull = ConvexHull.Create(CubeCorners);
            var r = new Random(seed);
            for (int i = 0; i < 150; i++)
            {
                BodyDef d = r.Next(4) == 0 ? BodyDef.Static(RandomVector(r, 8)) : BodyDef.Dynamic(RandomVector(r, 8));
                d.Rotation = RandomRotation(r);
                BodyHandle b = w.CreateBody(d);
                ShapeGeometry g = (i % 4) switch
                {
                    0 => ShapeGeometry.Sphere(0.2f + 0.5f * (float)r.NextDouble()),
                    1 => ShapeGeometry.Box(new Vector3(0.2f) + new Vector3((float)r.NextDouble(), (float)r.NextDouble(), (float)r.NextDouble()) * 0.5f),
                    2 => ShapeGeometry.Capsule(0.1f + 0.3f * (float)r.NextDouble(), 0.5f * (float)r.NextDouble()),
                    _ => ShapeGeometry.ConvexHull(hull),
                };
                ShapeDef sd = ShapeDef.Of(g);
                sd.Layer = i % 3;
                shapes.Add(w.AddShape(b, sd));
            }
            return w;
        }

        [Test]
        public void Ray_against_each_primitive_hits_at_the_closed_form_distance()
        {
            float t;
            Vector3 n;
            Assert.That(RayCaster.Cast(ShapeGeometry.Sphere(1), At(5, 0, 0), Vector3.Zero, Vector3.UnitX, 10, out t, out n), Is.True);
            Assert.That(t, Is.EqualTo(4f).Within(1e-5f));
            Assert.That(Vector3.Distance(n, -Vector3.UnitX), Is.LessThan(1e-5f));
            Assert.That(RayCaster.Cast(ShapeGeometry.Box(new Vector3(1, 2, 3)), At(new Vector3(0, 0, 10), AboutY(90)), Vector3.Zero, Vector3.UnitZ, 20, out t, out n), Is.True);
            Assert.That(t, Is.EqualTo(9f).Within(1e-5f));   // rotated: the x half-extent faces the ray
            Assert.That(Vector3.Distance(n, -Vector3.UnitZ), Is.LessThan(1e-5f));
            Assert.That(RayCaster.Cast(ShapeGeometry.Capsule(0.5f, 1), At(0, 0, 0), new Vector3(0, 5, 0), -Vector3.UnitY, 10, out t, out _), Is.True);
            Assert.That(t, Is.EqualTo(3.5f).Within(1e-5f));
            Assert.That(RayCaster.Cast(ShapeGeometry.Capsule(0.5f, 1), At(0, 0, 0), new Vector3(-5, 0.7f, 0), Vector3.UnitX, 10, out t, out n), Is.True);
            Assert.That(t, Is.EqualTo(4.5f).Within(1e-5f));
            Assert.That(RayCaster.Cast(ShapeGeometry.ConvexHull(CubeCorners), At(0, 0, 0), new Vector3(0, 5, 0), -Vector3.UnitY, 10, out t, out n), Is.True);
            Assert.That(t, Is.EqualTo(4.7f).Within(1e-5f));
            Assert.That(Vector3.Distance(n, Vector3.UnitY), Is.LessThan(1e-5f));
            Vector3 pn = Vector3.Normalize(new Vector3(0, 1, 1));
            Assert.That(RayCaster.Cast(ShapeGeometry.Plane(pn, 0), Pose.Identity, new Vector3(0, 3, 0), -Vector3.UnitY, 10, out t, out n), Is.True);
            Assert.That(t, Is.EqualTo(3f).Within(1e-5f));
            // Starting inside: no hit.
            Assert.That(RayCaster.Cast(ShapeGeometry.Sphere(1), At(0, 0, 0), Vector3.Zero, Vector3.UnitX, 10, out _, out _), Is.False);
            Assert.That(RayCaster.Cast(ShapeGeometry.Box(new Vector3(1)), At(0, 0, 0), Vector3.Zero, Vector3.UnitX, 10, out _, out _), Is.False);
        }

        [Test]
        public void Closest_and_all_hit_ray_casts_match_brute_force_over_the_world()
        {
            var w = MixedWorld(4, out var shapes);
            var r = new Random(17);
            var buffer = new RayHit[64];
            int hitsSeen = 0;
            for (int q = 0; q < 300; q++)
            {
                Vector3 o = RandomVector(r, 10), d = RandomVector(r, 1);
                if (d.LengthSquared() < 1e-4f) continue;
                float max = 5 + 15 * (float)r.NextDouble();
                uint mask = q % 5 == 0 ? 0b101u : uint.MaxValue;
                var filter = QueryFilter.Layers(mask);
                Vector3 u = Vector3.Normalize(d);
                var expected = new List<(float, int)>();
                foreach (ShapeHandle sh in shapes)
                {
                    if ((mask & (1u << w.Shapes.Layer[sh.Index])) == 0) continue;
                    if (RayCaster.Cast(w.GetShapeGeometry(sh), w.ShapeWorldPose(sh.Index), o, u, max, out float t, out _))
                        expected.Add((t, sh.Index));
                }
                expected.Sort();
                bool any = w.RayCast(o, d, max, filter, out RayHit hit);
                Assert.That(any, Is.EqualTo(expected.Count > 0), $"query {q}");
                if (any)
                {
                    hitsSeen++;
                    Assert.That(hit.Shape.Index, Is.EqualTo(expected[0].Item2), $"query {q}");
                    Assert.That(hit.Distance, Is.EqualTo(expected[0].Item1).Within(1e-5f));
                    Assert.That(Vector3.Distance(hit.Point, o + u * hit.Distance), Is.LessThan(1e-4f));
                }
                int n = w.RayCastAll(o, d, max, buffer, filter);
                Assert.That(n, Is.EqualTo(expected.Count));
                for (int i = 0; i < Math.Min(n, buffer.Length); i++) Assert.That(buffer[i].Distance, Is.EqualTo(expected[i].Item1).Within(1e-5f));
            }
            Assert.That(hitsSeen, Is.GreaterThan(50));
        }

        [Test]
        public void Ray_all_hits_into_a_short_span_keeps_the_nearest_and_counts_the_rest()
        {
            var w = new World();
            for (int i = 0; i < 6; i++)
                w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(3 * i + 2, 0, 0))), ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            var two = new RayHit[2];
            Assert.That(w.RayCastAll(Vector3.Zero, Vector3.UnitX, 100, two), Is.EqualTo(6));
            Assert.That(two[0].Distance, Is.EqualTo(1.5f).Within(1e-5f));
            Assert.That(two[1].Distance, Is.EqualTo(4.5f).Within(1e-5f));
        }

        [Test]
        public void Zero_or_nan_ray_direction_and_bad_distance_throw_naming_the_argument()
        {
            var w = new World();
            Assert.That(Assert.Throws<ArgumentException>(() => w.RayCast(Vector3.Zero, Vector3.Zero, 10, out _))!.ParamName, Is.EqualTo("direction"));
            Assert.That(Assert.Throws<ArgumentException>(() => w.RayCast(Vector3.Zero, new Vector3(float.NaN, 0, 0), 10, out _))!.ParamName, Is.EqualTo("direction"));
            Assert.That(Assert.Throws<ArgumentException>(() => w.RayCast(Vector3.Zero, Vector3.UnitX, float.NaN, out _))!.ParamName, Is.EqualTo("maxDistance"));
            Assert.That(Assert.Throws<ArgumentException>(() => w.RayCast(Vector3.Zero, Vector3.UnitX, -1, out _))!.ParamName, Is.EqualTo("maxDistance"));
            Assert.That(Assert.Throws<ArgumentException>(() => w.ShapeCast(ShapeGeometry.Sphere(1), Pose.Identity, Vector3.Zero, 1, out _))!.ParamName, Is.EqualTo("direction"));
            Assert.That(Assert.Throws<ArgumentException>(() => w.ShapeCast(ShapeGeometry.Plane(Vector3.UnitY, 0), Pose.Identity, Vector3.UnitX, 1, out _))!.ParamName, Is.EqualTo("shape"));
        }

        [Test]
        public void Sphere_cast_down_onto_a_box_stops_where_the_surfaces_meet()
        {
            var w = new World();
            BodyHandle box = w.CreateBody(BodyDef.Static(Vector3.Zero));
            ShapeHandle s = w.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(2, 0.5f, 2))));
            Assert.That(w.ShapeCast(ShapeGeometry.Sphere(0.5f), At(0.3f, 5, 0), -Vector3.UnitY, 10, out ShapeCastHit hit), Is.True);
            Assert.That(hit.Shape, Is.EqualTo(s));
            Assert.That(hit.Distance, Is.EqualTo(4f).Within(2e-4f));
            Assert.That(Vector3.Distance(hit.Normal, Vector3.UnitY), Is.LessThan(1e-3f));
            Assert.That(Vector3.Distance(hit.Point, new Vector3(0.3f, 0.5f, 0)), Is.LessThan(1e-3f));
            // Too short: no hit.
            Assert.That(w.ShapeCast(ShapeGeometry.Sphere(0.5f), At(0.3f, 5, 0), -Vector3.UnitY, 3.9f, out _), Is.False);
        }

        [Test]
        public void Shape_casts_match_a_brute_force_march_over_the_world()
        {
            var w = MixedWorld(8, out var shapes);
            var r = new Random(23);
            var cast = ShapeGeometry.Box(new Vector3(0.3f, 0.2f, 0.25f));
            int hits = 0;
            for (int q = 0; q < 60; q++)
            {
                var pose = new Pose(RandomVector(r, 9), RandomRotation(r));
                Vector3 d = Vector3.Normalize(RandomVector(r, 1) + new Vector3(0, 0, 1e-3f));
                float max = 8;
                // Brute force: the first sample along the path where the pair function reports overlap.
                var buffer = new ContactBuffer();
                bool startsOverlapped = false;
                float first = float.MaxValue;
                int steps = 1600;
                foreach (ShapeHandle sh in shapes)
                {
                    // Meshes are one-sided for casts: only motion into their front counts.
                    ShapeGeometry target = w.GetShapeGeometry(sh);
                    if (target.Type == ShapeType.TriangleMesh && Vector3.Dot(((TriangleMesh)target.Data!).Normals[0], d) >= 0) continue;
                    // Shapes nowhere near the path cannot be hit (only to save time).
                    Aabb from = cast.ComputeAabb(pose), to = cast.ComputeAabb(new Pose(pose.Position + d * max, pose.Rotation));
                    if (!Aabb.Union(from, to).Overlaps(target.ComputeAabb(w.ShapeWorldPose(sh.Index)))) continue;
                    for (int k = 0; k <= steps; k++)
                    {
                        float t = max * k / steps;
                        buffer.Clear(0);
                        CollisionTable.Collide(cast, new Pose(pose.Position + d * t, pose.Rotation), w.GetShapeGeometry(sh), w.ShapeWorldPose(sh.Index), buffer);
                        if (buffer.PointCount == 0) continue;
                        if (k == 0) startsOverlapped = true;
                        else first = MathF.Min(first, t);
                        break;
                    }
                }
                if (startsOverlapped) continue;
                bool any = w.ShapeCast(cast, pose, d, max, out ShapeCastHit hit);
                Assert.That(any, Is.EqualTo(first < float.MaxValue), $"query {q}: brute force {first}, cast {hit.Distance} on {hit.Shape}");
                if (!any) continue;
                hits++;
                Assert.That(hit.Distance, Is.EqualTo(first).Within(max / steps + 1e-3f), $"query {q}");
            }
            Assert.That(hits, Is.GreaterThan(10));
        }

        [Test]
        public void Overlap_matches_brute_force_and_respects_layers_and_sensors()
        {
            var w = MixedWorld(12, out var shapes);
            var r = new Random(31);
            var results = new ShapeHandle[256];
            var buffer = new ContactBuffer();
            for (int q = 0; q < 100; q++)
            {
                ShapeGeometry g = q % 2 == 0 ? ShapeGeometry.Sphere(1.5f) : ShapeGeometry.Box(new Vector3(1, 2, 0.5f));
                var pose = new Pose(RandomVector(r, 8), RandomRotation(r));
                uint mask = q % 3 == 0 ? 0b10u : uint.MaxValue;
                var expected = new List<int>();
                foreach (ShapeHandle sh in shapes)
                {
                    if ((mask & (1u << w.Shapes.Layer[sh.Index])) == 0) continue;
                    buffer.Clear(0);
                    CollisionTable.Collide(g, pose, w.GetShapeGeometry(sh), w.ShapeWorldPose(sh.Index), buffer);
                    if (buffer.PointCount > 0) expected.Add(sh.Index);
                }
                expected.Sort();
                int n = w.Overlap(g, pose, results, QueryFilter.Layers(mask));
                Assert.That(n, Is.EqualTo(expected.Count));
                for (int i = 0; i < n; i++) Assert.That(results[i].Index, Is.EqualTo(expected[i]));
            }
            // Sensors only with IncludeSensors.
            var w2 = new World();
            ShapeDef sensor = ShapeDef.Of(ShapeGeometry.Sphere(1));
            sensor.IsSensor = true;
            w2.AddShape(w2.CreateBody(BodyDef.Static(Vector3.Zero)), sensor);
            Assert.That(w2.Overlap(ShapeGeometry.Sphere(0.5f), Pose.Identity, results), Is.EqualTo(0));
            var withSensors = QueryFilter.Default;
            withSensors.IncludeSensors = true;
            Assert.That(w2.Overlap(ShapeGeometry.Sphere(0.5f), Pose.Identity, results, withSensors), Is.EqualTo(1));
        }

        [Test]
        public void Queries_see_bodies_where_the_last_step_left_them()
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            BodyHandle b = w.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            w.GetBody(b).LinearVelocity = new Vector3(300, 0, 0);   // 5 m in one step
            w.Step(1 / 60f);
            Assert.That(w.RayCast(new Vector3(5, 5, 0), -Vector3.UnitY, 10, out RayHit hit), Is.True);
            Assert.That(hit.Distance, Is.EqualTo(4.5f).Within(1e-4f));
        }

        [Test]
        public void Queries_allocate_nothing_once_warm()
        {
            var w = MixedWorld(5, out _);
            var hits = new RayHit[32];
            var casts = new ShapeCastHit[32];
            var over = new ShapeHandle[64];
            var sphere = ShapeGeometry.Sphere(0.5f);
            var origin = new Vector3(-9, 0.1f, 0.2f);
            var start = At(-9, 0.1f, 0.2f);
            long allocated = 0;
            for (int round = 0; round < 2; round++)
            {
                // Each call measured on its own, so that only the query is inside.
                long a = GC.GetAllocatedBytesForCurrentThread();
                w.RayCast(origin, Vector3.UnitX, 20, out _);
                long b = GC.GetAllocatedBytesForCurrentThread();
                w.RayCastAll(origin, Vector3.UnitX, 20, hits, QueryFilter.Default);
                long c = GC.GetAllocatedBytesForCurrentThread();
                w.ShapeCast(sphere, start, Vector3.UnitX, 20, out _);
                long d = GC.GetAllocatedBytesForCurrentThread();
                w.ShapeCastAll(sphere, start, Vector3.UnitX, 20, casts, QueryFilter.Default);
                long e = GC.GetAllocatedBytesForCurrentThread();
                w.Overlap(sphere, At(0, 0, 0), over, QueryFilter.Default);
                long f = GC.GetAllocatedBytesForCurrentThread();
                if (round == 1) allocated = (b - a) + (c - b) + (d - c) + (e - d) + (f - e);
            }
            Assert.That(allocated, Is.EqualTo(0));
        }
    }
}
