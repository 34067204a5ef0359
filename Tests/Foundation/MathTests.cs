using System;
using System.Numerics;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    public class MathTests
    {
        static readonly Random Rng = new Random(12345);

        static Vector3 RandomVector(float scale = 1f) =>
            new Vector3((float)Rng.NextDouble() * 2 - 1, (float)Rng.NextDouble() * 2 - 1, (float)Rng.NextDouble() * 2 - 1) * scale;

        static Quaternion RandomRotation() => Quaternion.Normalize(new Quaternion(RandomVector(), (float)Rng.NextDouble() * 2 - 1));

        static void AssertClose(Vector3 actual, Vector3 expected, float tol, string what = "")
        {
            Assert.That(Vector3.Distance(actual, expected), Is.LessThanOrEqualTo(tol), $"{what} expected {expected}, got {actual}");
        }

        [Test]
        public void Rotation_matrix_of_a_quaternion_rotates_like_the_quaternion()
        {
            for (int n = 0; n < 200; n++)
            {
                Quaternion q = RandomRotation();
                Vector3 v = RandomVector(3);
                AssertClose(Mat3.FromQuaternion(q) * v, Vector3.Transform(v, q), 1e-5f);
            }
        }

        [Test]
        public void Rotation_matrix_is_orthonormal_with_determinant_one()
        {
            for (int n = 0; n < 100; n++)
            {
                Mat3 r = Mat3.FromQuaternion(RandomRotation());
                Mat3 rtr = r.Transposed * r;
                Assert.That((rtr - Mat3.Identity).FrobeniusSquared, Is.LessThan(1e-10f));
                Assert.That(r.Determinant, Is.EqualTo(1f).Within(1e-5f));
            }
        }

        [Test]
        public void Matrix_from_quaternion_and_back_is_the_same_rotation()
        {
            for (int n = 0; n < 200; n++)
            {
                Quaternion q = RandomRotation();
                Quaternion back = Rotation.FromMatrix(Mat3.FromQuaternion(q));
                Assert.That(MathF.Abs(Quaternion.Dot(q, back)), Is.EqualTo(1f).Within(1e-5f));
            }
        }

        [Test]
        public void Inverse_times_matrix_is_identity()
        {
            for (int n = 0; n < 100; n++)
            {
                var m = new Mat3(RandomVector(2), RandomVector(2), RandomVector(2));
                if (MathF.Abs(m.Determinant) < 0.05f) continue;
                Assert.That(m.TryInvert(out Mat3 inv), Is.True);
                Assert.That((inv * m - Mat3.Identity).FrobeniusSquared, Is.LessThan(1e-8f));
                Assert.That((m * inv - Mat3.Identity).FrobeniusSquared, Is.LessThan(1e-8f));
            }
        }

        [Test]
        public void Singular_matrix_has_no_inverse_and_gives_zero()
        {
            Vector3 a = new Vector3(1, 2, 3);
            var m = new Mat3(a, 2 * a, new Vector3(0, 1, 0));
            Assert.That(m.TryInvert(out Mat3 inv), Is.False);
            Assert.That(inv, Is.EqualTo(Mat3.Zero));
        }

        [Test]
        public void Skew_matrix_is_the_cross_product_and_transposes_to_its_negative()
        {
            Vector3 a = new Vector3(0.3f, -1.2f, 2f), b = new Vector3(-0.7f, 0.4f, 1.1f);
            AssertClose(Mat3.Skew(a) * b, Vector3.Cross(a, b), 1e-6f);
            Assert.That((Mat3.Skew(a).Transposed + Mat3.Skew(a)).FrobeniusSquared, Is.EqualTo(0f));
        }

        [Test]
        public void Determinant_of_a_product_is_the_product_of_determinants()
        {
            var a = new Mat3(new Vector3(1, 2, 0), new Vector3(0, 1, 3), new Vector3(2, 0, 1));
            var b = new Mat3(new Vector3(2, 0, 1), new Vector3(1, 1, 0), new Vector3(0, 3, 1));
            Assert.That((a * b).Determinant, Is.EqualTo(a.Determinant * b.Determinant).Within(1e-4f));
            Assert.That(a.Transposed.Determinant, Is.EqualTo(a.Determinant).Within(1e-5f));
        }

        [Test]
        public void Exponential_map_and_its_inverse_round_trip()
        {
            foreach (float angle in new[] { 1e-6f, 1e-3f, 0.5f, 2f, 3.1f })
            {
                Vector3 axis = Vector3.Normalize(new Vector3(1, -2, 0.5f));
                Quaternion q = Rotation.FromRotationVector(axis * angle);
                Assert.That(q.Length(), Is.EqualTo(1f).Within(1e-6f));
                AssertClose(Rotation.ToRotationVector(q), axis * angle, 2e-5f * MathF.Max(1, angle), $"angle {angle}");
                Quaternion reference = Quaternion.CreateFromAxisAngle(axis, angle);
                Assert.That(MathF.Abs(Quaternion.Dot(q, reference)), Is.EqualTo(1f).Within(1e-6f));
            }
        }

        [Test]
        public void Angular_velocity_between_two_rotations_reaches_the_second_in_dt()
        {
            Quaternion a = RandomRotation(), b = RandomRotation();
            const float dt = 0.02f;
            Vector3 w = Rotation.AngularVelocityBetween(a, b, dt);
            Quaternion reached = Rotation.Integrate(a, w, dt);
            Assert.That(MathF.Abs(Quaternion.Dot(reached, b)), Is.EqualTo(1f).Within(1e-5f));
        }

        [Test]
        public void Jacobi_diagonalisation_recovers_a_rotated_diagonal_tensor()
        {
            for (int n = 0; n < 50; n++)
            {
                Vector3 d = new Vector3(1f + n % 3, 2.5f, 4f + 0.1f * n);
                Mat3 r = Mat3.FromQuaternion(RandomRotation());
                Mat3 m = Mat3.RotateDiagonal(r, d);
                Vector3 values = Rotation.Diagonalize(m, out Quaternion axes);
                Mat3 rebuilt = Mat3.RotateDiagonal(Mat3.FromQuaternion(axes), values);
                Assert.That((rebuilt - m).FrobeniusSquared, Is.LessThan(1e-8f * m.FrobeniusSquared));
                float[] sorted = { values.X, values.Y, values.Z };
                Array.Sort(sorted);
                float[] expected = { d.X, d.Y, d.Z };
                Array.Sort(expected);
                for (int k = 0; k < 3; k++) Assert.That(sorted[k], Is.EqualTo(expected[k]).Within(1e-4f));
            }
        }

        [Test]
        public void Pose_composition_and_inverse_are_consistent()
        {
            var a = new Pose(new Vector3(1, 2, 3), RandomRotation());
            var b = new Pose(new Vector3(-2, 0.5f, 1), RandomRotation());
            Vector3 p = new Vector3(0.3f, -0.4f, 0.5f);
            AssertClose((a * b).TransformPoint(p), a.TransformPoint(b.TransformPoint(p)), 1e-5f);
            AssertClose(a.Inverse().TransformPoint(a.TransformPoint(p)), p, 1e-5f);
            AssertClose(a.InverseTransformPoint(a.TransformPoint(p)), p, 1e-5f);
        }

        [Test]
        public void Transformed_box_bounds_hold_every_corner_and_are_tight_for_axis_rotations()
        {
            var pose = new Pose(new Vector3(1, 2, 3), RandomRotation());
            Vector3 e = new Vector3(0.5f, 1, 2);
            Aabb box = Aabb.Transform(pose, Vector3.Zero, e);
            for (int c = 0; c < 8; c++)
            {
                Vector3 corner = new Vector3((c & 1) != 0 ? e.X : -e.X, (c & 2) != 0 ? e.Y : -e.Y, (c & 4) != 0 ? e.Z : -e.Z);
                Assert.That(box.Expanded(1e-5f).Contains(pose.TransformPoint(corner)), Is.True);
            }
            Aabb turned = Aabb.Transform(new Pose(Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 2)), Vector3.Zero, e);
            AssertClose(turned.Extents, new Vector3(2, 1, 0.5f), 1e-5f);
        }
    }
}
