using System;
using System.Numerics;
using Fulcrum.Mathematics;
using NUnit.Framework;
using static Fulcrum.Tests.Collision.CollisionTestKit;

namespace Fulcrum.Tests.Collision
{
    public class CapsulePairTests
    {
        static readonly ShapeGeometry Cap = ShapeGeometry.Capsule(0.25f, 0.5f);

        [Test]
        public void Crossed_capsules_touch_in_one_point_at_the_segment_distance_minus_radii()
        {
            var b = Collide(Cap, At(0, 0, 0), Cap, At(new Vector3(0, 0, 0.49f), AboutZ(90)));
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.01f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], Vector3.UnitZ), Is.LessThan(1e-5f));
        }

        [Test]
        public void Parallel_capsules_side_by_side_touch_in_two_points_at_the_overlap_ends()
        {
            var b = Collide(Cap, At(0, 0, 0), Cap, At(0.49f, 0.3f, 0));
            Assert.That(b.PointCount, Is.EqualTo(2));
            float y0 = MathF.Min(b.Position[0].Y, b.Position[1].Y), y1 = MathF.Max(b.Position[0].Y, b.Position[1].Y);
            Assert.That(y0, Is.EqualTo(-0.2f).Within(1e-5f));
            Assert.That(y1, Is.EqualTo(0.5f).Within(1e-5f));
            Assert.That(b.Separation[0], Is.EqualTo(-0.01f).Within(1e-5f));
            Assert.That(b.Separation[1], Is.EqualTo(-0.01f).Within(1e-5f));
        }

        [Test]
        public void Coincident_capsules_get_a_unit_normal_perpendicular_to_the_axis()
        {
            var b = Collide(Cap, At(0, 0, 0), Cap, At(0, 0, 0));
            Assert.That(b.PointCount, Is.GreaterThan(0));
            Assert.That(b.PatchNormal[0].Length(), Is.EqualTo(1f).Within(1e-5f));
            Assert.That(MathF.Abs(b.PatchNormal[0].Y), Is.LessThan(1e-5f));
            Assert.That(b.MinSeparation(), Is.EqualTo(-0.5f).Within(1e-5f));
        }

        [Test]
        public void Capsule_lying_on_a_box_touches_in_two_points()
        {
            var box = ShapeGeometry.Box(new Vector3(2, 0.5f, 2));
            var b = Collide(box, At(0, 0, 0), Cap, At(new Vector3(0.2f, 0.745f, 0), AboutZ(90)));
            Assert.That(b.PointCount, Is.EqualTo(2));
            Assert.That(Vector3.Distance(b.PatchNormal[0], Vector3.UnitY), Is.LessThan(1e-5f));
            for (int i = 0; i < 2; i++)
            {
                Assert.That(b.Separation[i], Is.EqualTo(-0.005f).Within(1e-5f));
                Assert.That(MathF.Abs(b.Position[i].X - 0.2f), Is.EqualTo(0.5f).Within(1e-4f));
            }
        }

        [Test]
        public void Capsule_standing_on_a_box_touches_with_its_lower_cap_only()
        {
            var box = ShapeGeometry.Box(new Vector3(2, 0.5f, 2));
            var b = Collide(box, At(0, 0, 0), Cap, At(0.3f, 0.5f + 0.75f - 0.004f, 0));
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.004f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.Position[0], new Vector3(0.3f, 0.498f, 0)), Is.LessThan(1e-4f));
        }

        [Test]
        public void Capsule_sunk_into_a_box_is_pushed_out_through_the_top_face_with_two_points()
        {
            var box = ShapeGeometry.Box(new Vector3(2, 0.5f, 2));
            var b = Collide(box, At(0, 0, 0), Cap, At(new Vector3(0, 0.45f, 0), AboutZ(90)));
            Assert.That(b.PointCount, Is.EqualTo(2));
            Assert.That(Vector3.Distance(b.PatchNormal[0], Vector3.UnitY), Is.LessThan(1e-5f));
            Assert.That(b.Separation[0], Is.EqualTo(-0.3f).Within(1e-5f));
        }

        [Test]
        public void Capsule_against_a_box_edge_touches_at_the_edge()
        {
            // Capsule along z above the box edge x = 0.5, y = 0.5, approaching diagonally.
            var box = ShapeGeometry.Box(new Vector3(0.5f));
            Vector3 dir = Vector3.Normalize(new Vector3(1, 1, 0));
            var pose = At(new Vector3(0.5f, 0.5f, 0) + dir * 0.24f, AboutX(90));
            var b = Collide(box, At(0, 0, 0), Cap, pose);
            Assert.That(b.PointCount, Is.GreaterThan(0));
            Assert.That(b.MinSeparation(), Is.EqualTo(-0.01f).Within(1e-4f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], dir), Is.LessThan(1e-4f));
        }

        [Test]
        public void Capsule_on_a_plane_lying_flat_touches_with_both_ends()
        {
            var plane = ShapeGeometry.Plane(Vector3.UnitY, 0);
            var b = Collide(Cap, At(new Vector3(0, 0.249f, 0), AboutX(90)), plane, Pose.Identity);
            Assert.That(b.PointCount, Is.EqualTo(2));
            Assert.That(b.Separation[0], Is.EqualTo(-0.001f).Within(1e-5f));
        }
    }
}
