using System;
using System.Numerics;
using Fulcrum.Mathematics;
using NUnit.Framework;
using static Fulcrum.Tests.Collision.CollisionTestKit;

namespace Fulcrum.Tests.Collision
{
    public class BoxPairTests
    {
        static readonly ShapeGeometry Unit = ShapeGeometry.Box(new Vector3(0.5f));

        [Test]
        public void Box_resting_on_box_gives_four_corner_points_at_the_overlap_depth()
        {
            var big = ShapeGeometry.Box(new Vector3(2, 0.5f, 2));
            var b = Collide(big, At(0, 0, 0), Unit, At(0.1f, 0.995f, -0.2f));
            Assert.That(b.PatchCount, Is.EqualTo(1));
            Assert.That(b.PointCount, Is.EqualTo(4));
            Assert.That(Vector3.Distance(b.PatchNormal[0], Vector3.UnitY), Is.LessThan(1e-6f));
            for (int i = 0; i < 4; i++)
            {
                Assert.That(b.Separation[i], Is.EqualTo(-0.005f).Within(1e-5f));
                Assert.That(MathF.Abs(b.Position[i].X - 0.1f), Is.EqualTo(0.5f).Within(1e-5f));
                Assert.That(MathF.Abs(b.Position[i].Z + 0.2f), Is.EqualTo(0.5f).Within(1e-5f));
                Assert.That(b.Position[i].Y, Is.EqualTo(0.4975f).Within(1e-5f));
            }
        }

        [Test]
        public void Equal_boxes_stacked_with_parallel_faces_give_four_points_and_distinct_feature_ids()
        {
            var b = Collide(Unit, At(0, 0, 0), Unit, At(0, 0.99f, 0));
            Assert.That(b.PointCount, Is.EqualTo(4));
            var ids = new System.Collections.Generic.HashSet<uint>();
            for (int i = 0; i < 4; i++) ids.Add(b.Id[i]);
            Assert.That(ids.Count, Is.EqualTo(4));
            Assert.That(b.MinSeparation(), Is.EqualTo(-0.01f).Within(1e-5f));
        }

        [Test]
        public void Box_turned_45deg_on_a_box_clips_to_eight_points_and_keeps_four_spanning_the_octagon()
        {
            var b = Collide(Unit, At(0, 0, 0), Unit, At(new Vector3(0, 0.99f, 0), AboutY(45)));
            Assert.That(b.PointCount, Is.EqualTo(4));
            // The octagon's corners lie at distance 0.5 / cos(22.5 deg) .. 0.5 * sqrt(2) from the axis;
            // a well-spread choice has every kept point on the boundary.
            for (int i = 0; i < 4; i++)
            {
                float r = new Vector2(b.Position[i].X, b.Position[i].Z).Length();
                Assert.That(r, Is.GreaterThan(0.5f - 1e-4f));
                Assert.That(b.Separation[i], Is.EqualTo(-0.01f).Within(1e-5f));
            }
            // The largest quad inside a regular octagon of inradius r takes alternate corners:
            // a square of circumradius R = r / cos(22.5 deg), area 2 R^2 (0.5858 m^2 here).
            float circumradius = 0.5f / MathF.Cos(MathF.PI / 8);
            float area = QuadArea(b.Position[0], b.Position[1], b.Position[2], b.Position[3]);
            Assert.That(area, Is.EqualTo(2 * circumradius * circumradius).Within(1e-3f));
        }

        [Test]
        public void Boxes_apart_beyond_speculative_distance_give_nothing()
        {
            Assert.That(Collide(Unit, At(0, 0, 0), Unit, At(0, 1.03f, 0), 0.02f).PointCount, Is.EqualTo(0));
            var b = Collide(Unit, At(0, 0, 0), Unit, At(0, 1.01f, 0), 0.02f);
            Assert.That(b.PointCount, Is.EqualTo(4));
            Assert.That(b.Separation[0], Is.EqualTo(0.01f).Within(1e-5f));
        }

        [Test]
        public void Crossed_edges_meet_in_one_point_with_the_edge_cross_product_as_normal()
        {
            // Box A rotated 45 deg about z (an edge along z on top), box B rotated 45 deg about x
            // (an edge along x at the bottom), B just above A: edge-edge contact.
            float top = 0.5f * MathF.Sqrt(2);
            var pa = At(Vector3.Zero, AboutZ(45));
            var pb = At(new Vector3(0, 2 * top - 0.02f, 0), AboutX(45));
            var b = Collide(Unit, pa, Unit, pb);
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.02f).Within(1e-4f));
            Assert.That(Math.Abs(b.PatchNormal[0].Y), Is.EqualTo(1f).Within(1e-5f));
            Assert.That(b.PatchNormal[0].Y, Is.GreaterThan(0));
            Assert.That(Vector3.Distance(b.Position[0], new Vector3(0, top - 0.01f, 0)), Is.LessThan(1e-4f));
            Assert.That(b.Id[0] & 0x80000000u, Is.Not.EqualTo(0u));
        }

        [Test]
        public void Deeply_overlapping_boxes_separate_along_the_least_penetration_face()
        {
            var b = Collide(Unit, At(0, 0, 0), Unit, At(0.3f, 0.1f, 0.05f));
            Assert.That(b.PointCount, Is.GreaterThan(0));
            Assert.That(Vector3.Distance(b.PatchNormal[0], Vector3.UnitX), Is.LessThan(1e-6f));
            Assert.That(b.MinSeparation(), Is.EqualTo(-0.7f).Within(1e-5f));
        }

        [Test]
        public void Box_with_coincident_centre_gives_a_unit_face_normal_and_full_depth()
        {
            var b = Collide(Unit, At(0, 0, 0), ShapeGeometry.Box(new Vector3(0.5f, 0.25f, 0.5f)), At(0, 0, 0));
            Assert.That(b.PointCount, Is.GreaterThan(0));
            Assert.That(Math.Abs(b.PatchNormal[0].Y), Is.EqualTo(1f).Within(1e-6f));
            Assert.That(b.MinSeparation(), Is.EqualTo(-0.75f).Within(1e-5f));
        }

        [Test]
        public void Box_on_a_plane_gives_its_four_lowest_corners()
        {
            var plane = ShapeGeometry.Plane(Vector3.UnitY, 0);
            var b = Collide(Unit, At(new Vector3(3, 0.495f, 1), AboutY(20)), plane, Pose.Identity);
            Assert.That(b.PointCount, Is.EqualTo(4));
            for (int i = 0; i < 4; i++)
            {
                Assert.That(b.Separation[i], Is.EqualTo(-0.005f).Within(1e-5f));
                Assert.That(b.Position[i].Y, Is.EqualTo(-0.0025f).Within(1e-5f));
            }
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitY), Is.LessThan(1e-6f));
        }

        [Test]
        public void Tilted_box_on_a_plane_touches_with_its_lowest_edge_only()
        {
            var plane = ShapeGeometry.Plane(Vector3.UnitY, 0);
            float h = 0.5f * MathF.Sqrt(2);
            var b = Collide(Unit, At(new Vector3(0, h - 0.001f, 0), AboutZ(45)), plane, Pose.Identity);
            Assert.That(b.PointCount, Is.EqualTo(2));
            Assert.That(b.Separation[0], Is.EqualTo(-0.001f).Within(1e-5f));
        }

        static float QuadArea(Vector3 a, Vector3 b, Vector3 c, Vector3 d)
        {
            // Order the four points around their centroid, then the shoelace formula in xz.
            var pts = new[] { a, b, c, d };
            Vector3 m = (a + b + c + d) / 4;
            Array.Sort(pts, (p, q) => MathF.Atan2(p.Z - m.Z, p.X - m.X).CompareTo(MathF.Atan2(q.Z - m.Z, q.X - m.X)));
            float s = 0;
            for (int i = 0; i < 4; i++)
            {
                Vector3 p = pts[i], q = pts[(i + 1) % 4];
                s += p.X * q.Z - q.X * p.Z;
            }
            return MathF.Abs(s) / 2;
        }
    }
}
