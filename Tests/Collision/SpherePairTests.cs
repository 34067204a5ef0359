using System.Numerics;
using Fulcrum.Mathematics;
using NUnit.Framework;
using static Fulcrum.Tests.Collision.CollisionTestKit;

namespace Fulcrum.Tests.Collision
{
    public class SpherePairTests
    {
        static readonly ShapeGeometry Ball = ShapeGeometry.Sphere(0.5f);

        [Test]
        public void Spheres_overlapping_by_1cm_give_one_point_with_separation_minus_1cm_between_the_surfaces()
        {
            var b = Collide(Ball, At(0, 0, 0), ShapeGeometry.Sphere(0.25f), At(0.74f, 0, 0));
            Assert.That(b.PatchCount, Is.EqualTo(1));
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.01f).Within(1e-5f));
            Assert.That(b.PatchNormal[0].X, Is.EqualTo(1f).Within(1e-6f));
            Assert.That(b.Position[0].X, Is.EqualTo(0.495f).Within(1e-5f));
        }

        [Test]
        public void Spheres_apart_beyond_the_speculative_distance_give_nothing_and_within_it_a_positive_separation()
        {
            Assert.That(Collide(Ball, At(0, 0, 0), Ball, At(1.03f, 0, 0), 0.02f).PointCount, Is.EqualTo(0));
            var b = Collide(Ball, At(0, 0, 0), Ball, At(1.015f, 0, 0), 0.02f);
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(0.015f).Within(1e-5f));
        }

        [Test]
        public void Spheres_with_coincident_centres_separate_along_a_unit_normal_by_the_sum_of_radii()
        {
            var b = Collide(Ball, At(1, 2, 3), Ball, At(1, 2, 3));
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-1f).Within(1e-6f));
            Assert.That(b.PatchNormal[0].Length(), Is.EqualTo(1f).Within(1e-6f));
        }

        [Test]
        public void Sphere_above_box_face_touching_gives_normal_down_into_the_box_and_zero_separation()
        {
            var box = ShapeGeometry.Box(new Vector3(1, 0.5f, 1));
            var b = Collide(Ball, At(0.3f, 1.0f, -0.2f), box, At(0, 0, 0));
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(0f).Within(1e-6f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitY), Is.LessThan(1e-6f));
            Assert.That(Vector3.Distance(b.Position[0], new Vector3(0.3f, 0.5f, -0.2f)), Is.LessThan(1e-6f));
        }

        [Test]
        public void Sphere_near_a_rotated_box_corner_measures_the_distance_to_that_corner()
        {
            var box = ShapeGeometry.Box(new Vector3(0.5f));
            Quaternion q = AboutY(30);
            var pose = At(new Vector3(2, 0, 0), q);
            Vector3 corner = pose.TransformPoint(new Vector3(0.5f, 0.5f, 0.5f));
            Vector3 outward = Vector3.Normalize(pose.TransformDirection(new Vector3(1, 1, 1)));
            var b = Collide(Ball, At(corner + outward * 0.49f, Quaternion.Identity), box, pose);
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.01f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -outward), Is.LessThan(1e-4f));
        }

        [Test]
        public void Sphere_centre_inside_a_box_leaves_through_the_nearest_face()
        {
            var box = ShapeGeometry.Box(new Vector3(1, 1, 1));
            var b = Collide(Ball, At(0.2f, 0.9f, 0), box, At(0, 0, 0));
            Assert.That(b.Separation[0], Is.EqualTo(-0.6f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitY), Is.LessThan(1e-6f));
        }

        [Test]
        public void Sphere_against_capsule_side_uses_the_closest_point_of_the_segment()
        {
            var cap = ShapeGeometry.Capsule(0.25f, 1f);
            var b = Collide(Ball, At(0.7f, 0.5f, 0), cap, At(0, 0, 0));
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.05f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitX), Is.LessThan(1e-6f));
        }

        [Test]
        public void Sphere_against_capsule_cap_beyond_the_segment_end()
        {
            var cap = ShapeGeometry.Capsule(0.25f, 1f);
            var b = Collide(Ball, At(0, 1.7f, 0), cap, At(0, 0, 0));
            Assert.That(b.Separation[0], Is.EqualTo(-0.05f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitY), Is.LessThan(1e-6f));
        }

        [Test]
        public void Sphere_resting_on_a_tilted_plane_touches_along_the_plane_normal()
        {
            Vector3 n = Vector3.Normalize(new Vector3(1, 2, 0));
            var plane = ShapeGeometry.Plane(n, 1f);
            Vector3 c = n * (1f + 0.5f - 0.003f);
            var b = Collide(Ball, At(c, Quaternion.Identity), plane, Pose.Identity);
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.003f).Within(1e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -n), Is.LessThan(1e-6f));
        }
    }
}
