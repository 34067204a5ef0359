using System;
using System.Numerics;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class ShapeInputTests
    {
        [Test]
        public void Zero_negative_and_nan_sizes_are_rejected_naming_the_shape_field()
        {
            Assert.That(Assert.Throws<ArgumentException>(() => ShapeGeometry.Sphere(0))!.ParamName, Is.EqualTo("sphere.radius"));
            Assert.That(Assert.Throws<ArgumentException>(() => ShapeGeometry.Sphere(float.NaN))!.ParamName, Is.EqualTo("sphere.radius"));
            Assert.That(Assert.Throws<ArgumentException>(() => ShapeGeometry.Box(new Vector3(1, 0, 1)))!.ParamName, Is.EqualTo("box.halfExtents"));
            Assert.That(Assert.Throws<ArgumentException>(() => ShapeGeometry.Capsule(-1, 1))!.ParamName, Is.EqualTo("capsule.radius"));
            Assert.That(Assert.Throws<ArgumentException>(() => ShapeGeometry.Capsule(1, float.PositiveInfinity))!.ParamName, Is.EqualTo("capsule.halfHeight"));
            Assert.That(Assert.Throws<ArgumentException>(() => ShapeGeometry.Plane(Vector3.Zero, 0))!.ParamName, Is.EqualTo("plane.normal"));
            // A hull of zero volume: all points in one plane.
            var flat = new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitZ, new Vector3(1, 0, 1) };
            Assert.That(Assert.Throws<ArgumentException>(() => ShapeGeometry.ConvexHull(flat))!.ParamName, Is.EqualTo("hull.points"));
        }

        [Test]
        public void A_compound_body_gets_one_manifold_per_touching_shape_and_its_shapes_ignore_each_other()
        {
            var s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            var w = new World(s);
            w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0))), ShapeDef.Of(ShapeGeometry.Box(new Vector3(5, 0.5f, 5))));
            // A dumbbell: two spheres on a bar, lying on the ground.
            BodyHandle b = w.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.3f, 0)));
            ShapeDef left = ShapeDef.Of(ShapeGeometry.Sphere(0.3f));
            left.LocalPose = new Mathematics.Pose(new Vector3(-1, 0, 0), Quaternion.Identity);
            ShapeDef right = left;
            right.LocalPose = new Mathematics.Pose(new Vector3(1, 0, 0), Quaternion.Identity);
            ShapeDef bar = ShapeDef.Of(ShapeGeometry.Capsule(0.05f, 1));
            bar.LocalPose = new Mathematics.Pose(Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2));
            w.AddShape(b, left);
            w.AddShape(b, right);
            w.AddShape(b, bar);
            w.Step(1 / 60f);
            Assert.That(w.Contacts.ManifoldCount, Is.EqualTo(2));
            for (int k = 0; k < 2; k++)
            {
                Assert.That(w.Contacts[k].PointCount, Is.EqualTo(1));
                Assert.That(w.Contacts[k].Point0.Separation, Is.EqualTo(0f).Within(1e-5f));
            }
            Assert.That(MathF.Abs(w.Contacts[0].Point0.Position.X), Is.EqualTo(1f).Within(1e-5f));
        }
    }
}
