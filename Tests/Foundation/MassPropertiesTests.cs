using System;
using System.Numerics;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    public class MassPropertiesTests
    {
        [Test]
        public void Sphere_mass_and_inertia_match_closed_form()
        {
            MassProperties m = MassProperties.Sphere(0.5f, 1000f);
            double mass = 1000 * 4.0 / 3.0 * Math.PI * 0.125;
            Assert.That(m.Mass, Is.EqualTo(mass).Within(1e-5).Percent);
            Assert.That(m.Inertia.C0.X, Is.EqualTo(0.4 * mass * 0.25).Within(1e-5).Percent);
            Assert.That(m.Inertia.C1.Y, Is.EqualTo(m.Inertia.C0.X));
            Assert.That(m.Inertia.C0.Y, Is.EqualTo(0f));
        }

        [Test]
        public void Box_mass_and_inertia_match_closed_form()
        {
            // 1 x 2 x 3 m box at 500 kg/m^3: m = 3000 kg, Ixx = m/12 (b^2 + c^2).
            MassProperties m = MassProperties.Box(new Vector3(0.5f, 1f, 1.5f), 500f);
            Assert.That(m.Mass, Is.EqualTo(3000f).Within(1e-4f));
            Assert.That(m.Inertia.C0.X, Is.EqualTo(3000f / 12f * (4 + 9)).Within(1e-3f));
            Assert.That(m.Inertia.C1.Y, Is.EqualTo(3000f / 12f * (1 + 9)).Within(1e-3f));
            Assert.That(m.Inertia.C2.Z, Is.EqualTo(3000f / 12f * (1 + 4)).Within(1e-3f));
        }

        [Test]
        public void Capsule_matches_numerical_integration_over_its_volume()
        {
            const float r = 0.3f, h = 0.5f, rho = 800f;
            MassProperties m = MassProperties.Capsule(r, h, rho);
            // Midpoint-rule integration over a fine grid of the bounding box.
            int n = 120;
            double dx = 2 * r / n, dy = 2 * (h + r) / n, dz = 2 * r / n, dv = dx * dy * dz;
            double mass = 0, ixx = 0, iyy = 0;
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++)
                    for (int k = 0; k < n; k++)
                    {
                        double x = -r + (i + 0.5) * dx, y = -(h + r) + (j + 0.5) * dy, z = -r + (k + 0.5) * dz;
                        double ay = Math.Max(0, Math.Abs(y) - h);
                        if (x * x + z * z + ay * ay > r * r) continue;
                        mass += rho * dv;
                        ixx += rho * dv * (y * y + z * z);
                        iyy += rho * dv * (x * x + z * z);
                    }
            Assert.That(m.Mass, Is.EqualTo(mass).Within(0.5).Percent);
            Assert.That(m.Inertia.C0.X, Is.EqualTo(ixx).Within(0.5).Percent);
            Assert.That(m.Inertia.C1.Y, Is.EqualTo(iyy).Within(0.5).Percent);
            Assert.That(m.Inertia.C2.Z, Is.EqualTo(m.Inertia.C0.X));
        }

        [Test]
        public void Two_boxes_side_by_side_combine_into_the_box_that_holds_both()
        {
            MassProperties half = MassProperties.Box(new Vector3(0.5f, 0.5f, 0.5f), 1000f);
            MassProperties left = half.Transformed(new Pose(new Vector3(-0.5f, 0, 0), Quaternion.Identity));
            MassProperties right = half.Transformed(new Pose(new Vector3(0.5f, 0, 0), Quaternion.Identity));
            MassProperties both = MassProperties.Combine(left, right);
            MassProperties whole = MassProperties.Box(new Vector3(1f, 0.5f, 0.5f), 1000f);
            Assert.That(both.Mass, Is.EqualTo(whole.Mass).Within(1e-3f));
            Assert.That(both.Center.Length(), Is.LessThan(1e-6f));
            Assert.That((both.Inertia - whole.Inertia).FrobeniusSquared, Is.LessThan(1e-6f * whole.Inertia.FrobeniusSquared));
        }

        [Test]
        public void Rotating_a_box_rotates_its_tensor()
        {
            MassProperties box = MassProperties.Box(new Vector3(1f, 0.25f, 0.5f), 100f);
            Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2);
            MassProperties turned = box.Transformed(new Pose(Vector3.Zero, q));
            Assert.That(turned.Inertia.C0.X, Is.EqualTo(box.Inertia.C1.Y).Within(1e-3f));
            Assert.That(turned.Inertia.C1.Y, Is.EqualTo(box.Inertia.C0.X).Within(1e-3f));
        }

        [Test]
        public void Body_mass_comes_from_shape_density_or_from_the_mass_given()
        {
            var world = new World();
            BodyHandle a = world.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            world.AddShape(a, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            Assert.That(world.GetBody(a).Mass, Is.EqualTo(1000f).Within(1e-3f));

            BodyDef def = BodyDef.Dynamic(Vector3.Zero);
            def.Mass = 5f;
            BodyHandle b = world.CreateBody(def);
            world.AddShape(b, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            Assert.That(world.GetBody(b).Mass, Is.EqualTo(5f).Within(1e-5f));
            Assert.That(world.GetBody(b).InertiaLocal.C0.X, Is.EqualTo(5f / 6f).Within(1e-5f));
        }

        [Test]
        public void Offset_shape_moves_the_centre_of_mass()
        {
            var world = new World();
            BodyHandle b = world.CreateBody(BodyDef.Dynamic(new Vector3(10, 0, 0)));
            ShapeDef s = ShapeDef.Of(ShapeGeometry.Sphere(0.5f));
            s.LocalPose = new Pose(new Vector3(0, 1, 0), Quaternion.Identity);
            world.AddShape(b, s);
            Assert.That(world.GetBody(b).LocalCenterOfMass, Is.EqualTo(new Vector3(0, 1, 0)));
            Assert.That(world.GetBody(b).CenterOfMass, Is.EqualTo(new Vector3(10, 1, 0)));
        }
    }
}
