using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;
using NUnit.Framework;
using static Fulcrum.Tests.Collision.CollisionTestKit;

namespace Fulcrum.Tests.Collision
{
    public class HullPairTests
    {
        // A regular-ish tetrahedron with its base triangle at y = 0 and apex at y = 1.
        static readonly ShapeGeometry Tetra = ShapeGeometry.ConvexHull(new[]
        {
            new Vector3(-0.5f, 0, -0.4f), new Vector3(0.5f, 0, -0.4f), new Vector3(0, 0, 0.5f), new Vector3(0, 1, 0),
        });

        [Test]
        public void Tetrahedron_standing_on_a_box_touches_with_its_three_base_corners()
        {
            var box = ShapeGeometry.Box(new Vector3(2, 0.5f, 2));
            var b = Collide(box, At(0, 0, 0), Tetra, At(0.3f, 0.497f, 0.1f));
            Assert.That(b.PointCount, Is.EqualTo(3));
            Assert.That(Vector3.Distance(b.PatchNormal[0], Vector3.UnitY), Is.LessThan(1e-5f));
            for (int i = 0; i < 3; i++) Assert.That(b.Separation[i], Is.EqualTo(-0.003f).Within(2e-5f));
        }

        [Test]
        public void Tetrahedron_on_its_apex_touches_a_plane_in_one_point()
        {
            var plane = ShapeGeometry.Plane(Vector3.UnitY, 0);
            var b = Collide(Tetra, At(new Vector3(0, 0.999f, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI)), plane, Pose.Identity);
            Assert.That(b.PointCount, Is.EqualTo(1));
            Assert.That(b.Separation[0], Is.EqualTo(-0.001f).Within(1e-5f));
        }

        [Test]
        public void Sphere_over_a_hull_face_measures_the_face_distance_and_inside_it_the_depth()
        {
            var ball = ShapeGeometry.Sphere(0.25f);
            var near = Collide(ball, At(0.05f, -0.24f, 0), Tetra, At(0, 0, 0));
            Assert.That(near.PointCount, Is.EqualTo(1));
            Assert.That(near.Separation[0], Is.EqualTo(-0.01f).Within(1e-5f));
            Assert.That(Vector3.Distance(near.PatchNormal[0], Vector3.UnitY), Is.LessThan(1e-5f));
            // Centre just inside the base: leaves through the base (nearest face).
            var inside = Collide(ball, At(0, 0.05f, 0), Tetra, At(0, 0, 0));
            Assert.That(inside.Separation[0], Is.EqualTo(-0.3f).Within(1e-4f));
            Assert.That(Vector3.Distance(inside.PatchNormal[0], Vector3.UnitY), Is.LessThan(1e-4f));
        }

        [Test]
        public void Capsule_lying_on_a_hull_face_touches_in_two_points()
        {
            var cap = ShapeGeometry.Capsule(0.1f, 0.2f);
            var flipped = At(new Vector3(0, 1, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI));
            // The flipped tetrahedron's base is now its top face at y = 1.
            var b = Collide(cap, At(new Vector3(0, 1.098f, -0.05f), AboutZ(90)), Tetra, flipped);
            Assert.That(b.PointCount, Is.EqualTo(2));
            Assert.That(b.Separation[0], Is.EqualTo(-0.002f).Within(2e-5f));
            Assert.That(Vector3.Distance(b.PatchNormal[0], -Vector3.UnitY), Is.LessThan(1e-5f));
        }

        [Test]
        public void A_hull_resting_on_a_hull_keeps_its_feature_ids_step_after_step()
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            s.EnableSleeping = false;
            var w = new World(s);
            var corners = new Vector3[8];
            for (int i = 0; i < 8; i++) corners[i] = new Vector3((i & 1) != 0 ? 0.5f : -0.5f, (i & 2) != 0 ? 0.5f : -0.5f, (i & 4) != 0 ? 0.5f : -0.5f);
            var hull = ConvexHull.Create(corners);
            w.AddShape(w.CreateBody(BodyDef.Static(Vector3.Zero)), ShapeDef.Of(ShapeGeometry.ConvexHull(hull)));
            BodyDef top = BodyDef.Dynamic(new Vector3(0.1f, 0.996f, 0));
            top.Rotation = AboutY(20);
            w.AddShape(w.CreateBody(top), ShapeDef.Of(ShapeGeometry.ConvexHull(hull)));
            w.Step(1 / 60f);
            ContactManifold m = w.Contacts[0];
            Assert.That(m.PointCount, Is.EqualTo(4));
            for (int i = 0; i < 4; i++) Assert.That(ContactManifold.Point(ref m, i).Separation, Is.EqualTo(-0.004f).Within(2e-5f));
            var ids = new uint[4];
            for (int i = 0; i < 4; i++) ids[i] = ContactManifold.Point(ref m, i).FeatureId;
            for (int step = 0; step < 10; step++)
            {
                w.Step(1 / 60f);
                m = w.Contacts[0];
                Assert.That(m.PointCount, Is.EqualTo(4));
                for (int i = 0; i < 4; i++)
                {
                    ContactPoint p = ContactManifold.Point(ref m, i);
                    Assert.That(Array.IndexOf(ids, p.FeatureId), Is.GreaterThanOrEqualTo(0));
                    Assert.That(p.Persisted, Is.True);
                }
            }
        }
    }
}
