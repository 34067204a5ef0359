using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class ConvexHullTests
    {
        static Vector3[] CubeCorners(Vector3 h, Vector3 offset)
        {
            var p = new List<Vector3>();
            for (int i = 0; i < 8; i++)
                p.Add(offset + new Vector3((i & 1) != 0 ? h.X : -h.X, (i & 2) != 0 ? h.Y : -h.Y, (i & 4) != 0 ? h.Z : -h.Z));
            return p.ToArray();
        }

        static void AssertValid(ConvexHull hull, IEnumerable<Vector3> input, float tolerance)
        {
            // Every input point lies inside every face plane; faces are planar, convex, outward.
            // Worst cases are gathered first: one assertion per property keeps this fast.
            Vector3 c = hull.Centroid;
            float worstNormal = 0, worstPlanar = 0, worstConvex = 0, worstOutside = float.MinValue, worstInward = float.MinValue;
            int smallestFace = int.MaxValue;
            for (int f = 0; f < hull.FaceCount; f++)
            {
                Vector3 n = hull.GetFaceNormal(f);
                worstNormal = MathF.Max(worstNormal, MathF.Abs(n.Length() - 1));
                ReadOnlySpan<int> face = hull.GetFace(f);
                smallestFace = Math.Min(smallestFace, face.Length);
                float offset = Vector3.Dot(n, hull.GetVertex(face[0]));
                worstInward = MathF.Max(worstInward, Vector3.Dot(n, c) - offset);
                for (int i = 0; i < face.Length; i++)
                {
                    Vector3 p = hull.GetVertex(face[i]), q = hull.GetVertex(face[(i + 1) % face.Length]), r = hull.GetVertex(face[(i + 2) % face.Length]);
                    worstPlanar = MathF.Max(worstPlanar, MathF.Abs(Vector3.Dot(n, p) - offset));
                    worstConvex = MathF.Max(worstConvex, -Vector3.Dot(Vector3.Cross(q - p, r - q), n));
                }
                foreach (Vector3 p in input) worstOutside = MathF.Max(worstOutside, Vector3.Dot(n, p) - offset);
            }
            Assert.That(worstNormal, Is.LessThan(1e-5f), "normal not unit");
            Assert.That(smallestFace, Is.GreaterThanOrEqualTo(3));
            Assert.That(worstInward, Is.LessThan(0), "normal points inwards");
            Assert.That(worstPlanar, Is.LessThan(tolerance), "face not planar");
            Assert.That(worstConvex, Is.LessThan(tolerance), "face not convex / not counter-clockwise");
            Assert.That(worstOutside, Is.LessThan(tolerance), "point outside the hull");
            // Euler's formula for a convex polyhedron.
            Assert.That(hull.VertexCount - hull.EdgeCount + hull.FaceCount, Is.EqualTo(2));
        }

        [Test]
        public void Cube_with_duplicate_interior_and_coplanar_points_gives_8_vertices_6_quads_12_edges()
        {
            var pts = new List<Vector3>(CubeCorners(new Vector3(1, 2, 3), Vector3.Zero));
            pts.AddRange(CubeCorners(new Vector3(1, 2, 3), Vector3.Zero));          // duplicates
            pts.Add(Vector3.Zero);                                                   // interior
            pts.Add(new Vector3(0.3f, -0.5f, 1));
            pts.Add(new Vector3(1, 0, 0)); pts.Add(new Vector3(0, 2, 1)); pts.Add(new Vector3(-1, 1, -2)); // on faces
            pts.Add(new Vector3(1, 2, 0)); pts.Add(new Vector3(0, -2, -3));                                // on edges
            var hull = ConvexHull.Create(pts.ToArray());
            Assert.That(hull.VertexCount, Is.EqualTo(8));
            Assert.That(hull.FaceCount, Is.EqualTo(6));
            Assert.That(hull.EdgeCount, Is.EqualTo(12));
            for (int f = 0; f < 6; f++) Assert.That(hull.GetFace(f).Length, Is.EqualTo(4));
            AssertValid(hull, pts, 1e-5f);
            Assert.That(hull.Volume, Is.EqualTo(48f).Within(1e-4f));
        }

        [Test]
        public void Hull_of_a_box_has_exactly_the_box_mass_properties()
        {
            Vector3 h = new Vector3(0.5f, 1, 1.5f), offset = new Vector3(1, -2, 3);
            var hull = ConvexHull.Create(CubeCorners(h, offset));
            MassProperties m = hull.ComputeMass(700);
            MassProperties box = MassProperties.Box(h, 700);
            Assert.That(m.Mass, Is.EqualTo(box.Mass).Within(1e-3f));
            Assert.That(Vector3.Distance(m.Center, offset), Is.LessThan(1e-5f));
            Assert.That((m.Inertia - box.Inertia).FrobeniusSquared, Is.LessThan(1e-6f * box.Inertia.FrobeniusSquared));
        }

        [Test]
        public void Tetrahedron_mass_properties_match_the_closed_form()
        {
            // Right tetrahedron (0, a e1, a e2, a e3): V = a^3/6, centroid a/4 (1,1,1),
            // inertia about the centroid: Ixx = 3/40 m a^2, Ixy = +1/80 m a^2 (covariance 3/80 and -1/80).
            float a = 2;
            var hull = ConvexHull.Create(new[] { Vector3.Zero, new Vector3(a, 0, 0), new Vector3(0, a, 0), new Vector3(0, 0, a) });
            MassProperties m = hull.ComputeMass(1);
            float mass = a * a * a / 6;
            Assert.That(m.Mass, Is.EqualTo(mass).Within(1e-5f));
            Assert.That(Vector3.Distance(m.Center, new Vector3(a / 4)), Is.LessThan(1e-6f));
            Assert.That(m.Inertia[0, 0], Is.EqualTo(3f / 40 * mass * a * a).Within(1e-5f));
            Assert.That(m.Inertia[0, 1], Is.EqualTo(1f / 80 * mass * a * a).Within(1e-5f));
            Assert.That(m.Inertia[1, 2], Is.EqualTo(1f / 80 * mass * a * a).Within(1e-5f));
        }

        [Test]
        public void Random_points_on_a_sphere_give_a_valid_hull_with_the_right_volume()
        {
            var r = new Random(1);
            var pts = new Vector3[2000];
            for (int i = 0; i < pts.Length; i++) pts[i] = Vector3.Normalize(CollisionTestKit.RandomVector(r, 1) + new Vector3(1e-4f)) * 2;
            var hull = ConvexHull.Create(pts);
            AssertValid(hull, pts, 1e-4f);
            // Inscribed in the sphere of radius 2 and close to it.
            float sphere = 4f / 3 * MathF.PI * 8;
            Assert.That(hull.Volume, Is.LessThan(sphere));
            Assert.That(hull.Volume, Is.GreaterThan(0.97f * sphere));
        }

        [Test]
        public void Noisy_coplanar_grid_on_each_face_of_a_box_merges_into_six_faces()
        {
            var r = new Random(2);
            var pts = new List<Vector3>();
            for (int face = 0; face < 6; face++)
                for (int i = 0; i < 15; i++)
                    for (int j = 0; j < 15; j++)
                    {
                        float u = -1 + 2 * i / 14f, v = -1 + 2 * j / 14f;
                        float jitter = (float)(r.NextDouble() - 0.5) * 1e-7f;
                        Vector3 p = (face >> 1) switch
                        {
                            0 => new Vector3(face % 2 == 0 ? 1 + jitter : -1 - jitter, u, v),
                            1 => new Vector3(u, face % 2 == 0 ? 1 + jitter : -1 - jitter, v),
                            _ => new Vector3(u, v, face % 2 == 0 ? 1 + jitter : -1 - jitter),
                        };
                        pts.Add(p);
                    }
            var hull = ConvexHull.Create(pts.ToArray());
            Assert.That(hull.FaceCount, Is.EqualTo(6));
            Assert.That(hull.Volume, Is.EqualTo(8f).Within(1e-3f));
            AssertValid(hull, pts, 1e-5f);
        }

        [Test]
        public void Sliver_tetrahedron_and_near_degenerate_clouds_still_build()
        {
            var sliver = new[] { new Vector3(0, 0, 0), new Vector3(1, 0, 0), new Vector3(0, 1, 0), new Vector3(0.3f, 0.3f, 1e-3f) };
            var hull = ConvexHull.Create(sliver);
            Assert.That(hull.VertexCount, Is.EqualTo(4));
            Assert.That(hull.Volume, Is.EqualTo(1e-3f / 6).Within(1e-6f));
            // A long thin needle with points along its axis.
            var needle = new List<Vector3>();
            for (int i = 0; i <= 100; i++) needle.Add(new Vector3(i * 0.1f, 0, 0));
            needle.Add(new Vector3(5, 0.01f, 0)); needle.Add(new Vector3(5, 0, 0.01f)); needle.Add(new Vector3(5, -0.01f, -0.01f));
            var h2 = ConvexHull.Create(needle.ToArray());
            AssertValid(h2, needle, 1e-5f);
        }

        [TestCase(3)]
        [TestCase(0)]
        public void Fewer_than_four_points_are_rejected_naming_the_points(int n)
        {
            var pts = new Vector3[n];
            for (int i = 0; i < n; i++) pts[i] = new Vector3(i, i * i, 0);
            var e = Assert.Throws<ArgumentException>(() => ConvexHull.Create(pts));
            Assert.That(e!.ParamName, Is.EqualTo("hull.points"));
        }

        [Test]
        public void Coincident_collinear_coplanar_and_nan_clouds_are_rejected_naming_the_points()
        {
            var same = new[] { Vector3.One, Vector3.One, Vector3.One, Vector3.One, Vector3.One };
            var line = new[] { Vector3.Zero, Vector3.One, 2 * Vector3.One, 3 * Vector3.One };
            var flat = new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitY, new Vector3(1, 1, 0), new Vector3(0.5f, 0.2f, 0) };
            var nan = new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitY, new Vector3(0, 0, float.NaN) };
            foreach (var cloud in new[] { same, line, flat, nan })
            {
                var e = Assert.Throws<ArgumentException>(() => ConvexHull.Create(cloud));
                Assert.That(e!.ParamName, Is.EqualTo("hull.points"));
            }
            StringAssert.Contains("coplanar", Assert.Throws<ArgumentException>(() => ConvexHull.Create(flat))!.Message);
        }

        [Test]
        public void A_dynamic_hull_body_takes_its_mass_from_the_hull()
        {
            var w = new World();
            BodyHandle b = w.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            ShapeDef d = ShapeDef.Of(ShapeGeometry.ConvexHull(CubeCorners(new Vector3(0.5f), new Vector3(0, 1, 0))));
            d.Density = 500;
            w.AddShape(b, d);
            Assert.That(w.GetBody(b).Mass, Is.EqualTo(500f).Within(1e-3f));
            Assert.That(Vector3.Distance(w.GetBody(b).LocalCenterOfMass, new Vector3(0, 1, 0)), Is.LessThan(1e-5f));
        }
    }
}
