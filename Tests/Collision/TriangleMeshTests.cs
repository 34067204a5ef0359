using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;
using NUnit.Framework;
using static Fulcrum.Tests.Collision.CollisionTestKit;

namespace Fulcrum.Tests.Collision
{
    public class TriangleMeshTests
    {
        // A square floor of 2 x 2 cells (8 triangles) at y = 0, facing up.
        static TriangleMesh Floor(float half = 2)
        {
            var v = new List<Vector3>();
            var t = new List<int>();
            for (int z = 0; z <= 2; z++)
                for (int x = 0; x <= 2; x++)
                    v.Add(new Vector3(-half + x * half, 0, -half + z * half));
            for (int z = 0; z < 2; z++)
                for (int x = 0; x < 2; x++)
                {
                    int i = z * 3 + x;
                    t.AddRange(new[] { i, i + 3, i + 1, i + 1, i + 3, i + 4 });
                }
            return TriangleMesh.Create(v.ToArray(), t.ToArray());
        }

        [Test]
        public void Floor_triangles_face_up()
        {
            var mesh = Floor();
            for (int i = 0; i < mesh.TriangleCount; i++)
                Assert.That(Vector3.Distance(mesh.Normals[i], Vector3.UnitY), Is.LessThan(1e-6f));
        }

        [Test]
        public void Box_resting_across_triangle_edges_gets_one_manifold_with_its_four_corners()
        {
            var floor = ShapeGeometry.TriangleMesh(Floor());
            var box = ShapeGeometry.Box(new Vector3(0.5f));
            var b = Collide(box, At(new Vector3(0.1f, 0.497f, -0.2f), AboutY(30)), floor, Pose.Identity);
            Assert.That(b.PatchCount, Is.EqualTo(1));
            Assert.That(b.PointCount, Is.EqualTo(4));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitY), Is.LessThan(1e-5f));
            var corners = new HashSet<(int, int)>();
            for (int i = 0; i < 4; i++)
            {
                Assert.That(b.Separation[i], Is.EqualTo(-0.003f).Within(1e-5f));
                Vector3 local = Vector3.Transform(b.Position[i] - new Vector3(0.1f, 0, -0.2f), Quaternion.Conjugate(AboutY(30)));
                Assert.That(MathF.Abs(local.X), Is.EqualTo(0.5f).Within(1e-4f));
                Assert.That(MathF.Abs(local.Z), Is.EqualTo(0.5f).Within(1e-4f));
                corners.Add((MathF.Sign(local.X), MathF.Sign(local.Z)));
            }
            Assert.That(corners.Count, Is.EqualTo(4));
        }

        [Test]
        public void Sphere_on_a_shared_mesh_vertex_gets_a_single_point()
        {
            var floor = ShapeGeometry.TriangleMesh(Floor());
            var b = Collide(ShapeGeometry.Sphere(0.5f), At(0, 0.49f, 0), floor, Pose.Identity);
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.01f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitY), Is.LessThan(1e-5f));
        }

        [Test]
        public void Sphere_sunk_below_the_surface_is_pushed_out_along_the_triangle_normal()
        {
            var floor = ShapeGeometry.TriangleMesh(Floor());
            var b = Collide(ShapeGeometry.Sphere(0.5f), At(0.7f, -0.1f, 0.3f), floor, Pose.Identity);
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.6f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitY), Is.LessThan(1e-5f));
        }

        [Test]
        public void Shape_entirely_below_a_one_sided_floor_collides_with_nothing()
        {
            var floor = ShapeGeometry.TriangleMesh(Floor());
            var b = Collide(ShapeGeometry.Box(new Vector3(0.5f)), At(0, -0.51f, 0), floor, Pose.Identity, 0.05f);
            Assert.That(b.PointCount, Is.EqualTo(0));
        }

        [Test]
        public void Box_in_a_corner_of_floor_and_wall_gets_one_manifold_per_surface()
        {
            // Floor (y = 0) and a wall (x = 1) facing -x, as one mesh.
            var v = new[]
            {
                new Vector3(-3, 0, -3), new Vector3(1, 0, -3), new Vector3(1, 0, 3), new Vector3(-3, 0, 3),
                new Vector3(1, 0, -3), new Vector3(1, 3, -3), new Vector3(1, 3, 3), new Vector3(1, 0, 3),
            };
            var t = new[] { 0, 3, 2, 0, 2, 1, 4, 7, 6, 4, 6, 5 };
            var mesh = TriangleMesh.Create(v, t);
            Assert.That(Vector3.Distance(mesh.Normals[2], -Vector3.UnitX), Is.LessThan(1e-6f));
            var b = Collide(ShapeGeometry.Box(new Vector3(0.5f)), At(0.498f, 0.497f, 0), ShapeGeometry.TriangleMesh(mesh), Pose.Identity);
            Assert.That(b.PatchCount, Is.EqualTo(2));
            var normals = new List<Vector3> { b.PatchNormal[0], b.PatchNormal[1] };
            Assert.That(normals.Exists(n => Vector3.Distance(n, -Vector3.UnitY) < 1e-5f), Is.True);
            Assert.That(normals.Exists(n => Vector3.Distance(n, Vector3.UnitX) < 1e-5f), Is.True);
            Assert.That(b.PatchPointCount(0), Is.EqualTo(4));
            Assert.That(b.PatchPointCount(1), Is.EqualTo(4));
        }

        [Test]
        public void Capsule_lying_on_a_mesh_touches_in_two_points()
        {
            var floor = ShapeGeometry.TriangleMesh(Floor());
            var b = Collide(ShapeGeometry.Capsule(0.2f, 0.8f), At(new Vector3(0.3f, 0.198f, 0.1f), AboutZ(90)), floor, Pose.Identity);
            Assert.That(b.PointCount, Is.EqualTo(2));
            Assert.That(b.Separation[0], Is.EqualTo(-0.002f).Within(1e-5f));
            Assert.That(b.Separation[1], Is.EqualTo(-0.002f).Within(1e-5f));
        }

        [Test]
        public void Box_falling_onto_a_mesh_in_a_world_makes_a_manifold_and_a_mesh_on_a_dynamic_body_is_refused()
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            var mesh = Floor();
            w.AddShape(w.CreateBody(BodyDef.Static(Vector3.Zero)), ShapeDef.Of(ShapeGeometry.TriangleMesh(mesh)));
            BodyHandle box = w.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.499f, 0)));
            w.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(1));
            Assert.That(w.Contacts[0].PointCount, Is.EqualTo(4));
            BodyHandle dyn = w.CreateBody(BodyDef.Dynamic(new Vector3(5, 5, 5)));
            Assert.Throws<ArgumentException>(() => w.AddShape(dyn, ShapeDef.Of(ShapeGeometry.TriangleMesh(mesh))));
        }

        [Test]
        public void Bad_meshes_are_rejected_naming_the_field()
        {
            var v = new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitZ, new Vector3(2, 0, 0) };
            Assert.That(Assert.Throws<ArgumentException>(() => TriangleMesh.Create(v, new[] { 0, 1, 3 }))!.ParamName, Is.EqualTo("mesh.triangles"), "collinear triangle");
            Assert.That(Assert.Throws<ArgumentException>(() => TriangleMesh.Create(v, new[] { 0, 1, 1 }))!.ParamName, Is.EqualTo("mesh.triangles"), "repeated vertex");
            Assert.That(Assert.Throws<ArgumentException>(() => TriangleMesh.Create(v, new[] { 0, 1, 7 }))!.ParamName, Is.EqualTo("mesh.triangles"), "index out of range");
            Assert.That(Assert.Throws<ArgumentException>(() => TriangleMesh.Create(v, new[] { 0, 1 }))!.ParamName, Is.EqualTo("mesh.triangles"), "not a multiple of 3");
            Assert.That(Assert.Throws<ArgumentException>(() => TriangleMesh.Create(v, Array.Empty<int>()))!.ParamName, Is.EqualTo("mesh.triangles"), "empty");
            var nan = new[] { Vector3.Zero, new Vector3(float.NaN, 0, 0), Vector3.UnitZ };
            Assert.That(Assert.Throws<ArgumentException>(() => TriangleMesh.Create(nan, new[] { 0, 1, 2 }))!.ParamName, Is.EqualTo("mesh.vertices"));
            StringAssert.Contains("degenerate", Assert.Throws<ArgumentException>(() => TriangleMesh.Create(v, new[] { 0, 1, 3 }))!.Message);
        }

        struct Collect : ITreeOverlapCallback
        {
            public List<int> Found;
            public bool Visit(int proxyId, int userData) { Found.Add(userData); return true; }
        }

        [Test]
        public void Bvh_query_returns_every_triangle_whose_bounds_overlap_and_few_others()
        {
            var r = new Random(9);
            var v = new List<Vector3>();
            var t = new List<int>();
            for (int i = 0; i < 3000; i++)
            {
                Vector3 c = RandomVector(r, 20);
                v.Add(c + RandomVector(r, 1)); v.Add(c + RandomVector(r, 1)); v.Add(c + RandomVector(r, 1));
                t.Add(3 * i); t.Add(3 * i + 1); t.Add(3 * i + 2);
            }
            var mesh = TriangleMesh.Create(v.ToArray(), t.ToArray());
            Assert.That(mesh.BvhDepth, Is.LessThan(24));
            for (int q = 0; q < 100; q++)
            {
                Aabb box = Aabb.FromCenterExtents(RandomVector(r, 20), new Vector3(2));
                var c = new Collect { Found = new List<int>() };
                mesh.Bvh.Query(box, ref c);
                var expected = new List<int>();
                for (int i = 0; i < mesh.TriangleCount; i++)
                {
                    mesh.GetTriangle(i, out Vector3 a, out Vector3 b, out Vector3 cc);
                    var tb = new Aabb(Vector3.Min(a, Vector3.Min(b, cc)), Vector3.Max(a, Vector3.Max(b, cc)));
                    if (tb.Overlaps(box)) expected.Add(i);
                }
                // Leaves hand out all their triangles: a superset, but not a loose one.
                Assert.That(c.Found, Is.SupersetOf(expected));
                Assert.That(c.Found.Count, Is.LessThanOrEqualTo(4 * expected.Count + 16));
            }
        }
    }
}
