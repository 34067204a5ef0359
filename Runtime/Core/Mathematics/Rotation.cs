using System;
using System.Numerics;

namespace Fulcrum.Mathematics
{
    /// <summary>Quaternion operations System.Numerics does not have.</summary>
    public static class Rotation
    {
        /// <summary>
        /// The rotation by angle |<paramref name="rotationVector"/>| about its direction (the
        /// exponential map). Exact for any angle; falls back to the first-order series below
        /// 1e-4 rad, where the closed form loses precision in float.
        /// </summary>
        public static Quaternion FromRotationVector(Vector3 rotationVector)
        {
            float angle = rotationVector.Length();
            if (angle < 1e-4f)
            {
                Vector3 h = 0.5f * rotationVector;
                return Quaternion.Normalize(new Quaternion(h, 1f));
            }
            float half = 0.5f * angle;
            float s = MathF.Sin(half) / angle;
            return new Quaternion(rotationVector * s, MathF.Cos(half));
        }

        /// <summary>
        /// The rotation vector (axis times angle, angle in [0, pi]) of a unit quaternion: the
        /// inverse of <see cref="FromRotationVector"/> along the shortest arc.
        /// </summary>
        public static Vector3 ToRotationVector(Quaternion q)
        {
            if (q.W < 0) q = new Quaternion(-q.X, -q.Y, -q.Z, -q.W);
            Vector3 v = new Vector3(q.X, q.Y, q.Z);
            float s = v.Length();
            if (s < 1e-6f) return 2f * v;
            float angle = 2f * MathF.Atan2(s, q.W);
            return v * (angle / s);
        }

        /// <summary>
        /// Advances an orientation by a constant world angular velocity over <paramref name="dt"/>:
        /// q' = exp(omega dt) q, renormalised so that float error never accumulates.
        /// </summary>
        public static Quaternion Integrate(Quaternion q, Vector3 angularVelocity, float dt) =>
            Quaternion.Normalize(FromRotationVector(angularVelocity * dt) * q);

        /// <summary>
        /// The constant angular velocity that turns <paramref name="from"/> into
        /// <paramref name="to"/> in <paramref name="dt"/> seconds, along the shortest arc.
        /// </summary>
        public static Vector3 AngularVelocityBetween(Quaternion from, Quaternion to, float dt) =>
            ToRotationVector(to * Quaternion.Conjugate(from)) / dt;

        /// <summary>The rotation of angle <paramref name="angle"/> (radians) about principal axis 0, 1 or 2.</summary>
        public static Quaternion AboutAxis(int axis, float angle)
        {
            float s = MathF.Sin(0.5f * angle), c = MathF.Cos(0.5f * angle);
            return axis == 0 ? new Quaternion(s, 0, 0, c) : axis == 1 ? new Quaternion(0, s, 0, c) : new Quaternion(0, 0, s, c);
        }

        /// <summary>
        /// Jacobi eigen-decomposition of a symmetric matrix: returns the eigenvalues and the
        /// rotation whose columns are the eigenvectors, so that m = R diag(values) R^T. Used to
        /// find the principal axes of an inertia tensor.
        /// </summary>
        public static Vector3 Diagonalize(in Mat3 m, out Quaternion axes)
        {
            // Cyclic Jacobi sweeps in double: each sweep zeroes one off-diagonal pair by a
            // plane rotation; converges quadratically for symmetric matrices.
            Span<double> a = stackalloc double[9];
            Span<double> v = stackalloc double[9];
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++)
                {
                    a[r * 3 + c] = 0.5 * (m[r, c] + m[c, r]);
                    v[r * 3 + c] = r == c ? 1 : 0;
                }
            for (int sweep = 0; sweep < 50; sweep++)
            {
                double off = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
                double diag = a[0] * a[0] + a[4] * a[4] + a[8] * a[8];
                if (off <= 1e-30 * diag || off == 0) break;
                for (int p = 0; p < 2; p++)
                    for (int q = p + 1; q < 3; q++)
                    {
                        double apq = a[p * 3 + q];
                        if (apq == 0) continue;
                        double app = a[p * 3 + p], aqq = a[q * 3 + q];
                        double theta = (aqq - app) / (2 * apq);
                        double t = Math.Sign(theta) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1));
                        if (theta == 0) t = 1;
                        double c = 1 / Math.Sqrt(t * t + 1), s = t * c;
                        for (int k = 0; k < 3; k++)
                        {
                            double akp = a[k * 3 + p], akq = a[k * 3 + q];
                            a[k * 3 + p] = c * akp - s * akq;
                            a[k * 3 + q] = s * akp + c * akq;
                        }
                        for (int k = 0; k < 3; k++)
                        {
                            double apk = a[p * 3 + k], aqk = a[q * 3 + k];
                            a[p * 3 + k] = c * apk - s * aqk;
                            a[q * 3 + k] = s * apk + c * aqk;
                        }
                        for (int k = 0; k < 3; k++)
                        {
                            double vkp = v[k * 3 + p], vkq = v[k * 3 + q];
                            v[k * 3 + p] = c * vkp - s * vkq;
                            v[k * 3 + q] = s * vkp + c * vkq;
                        }
                    }
            }
            var c0 = new Vector3((float)v[0], (float)v[3], (float)v[6]);
            var c1 = new Vector3((float)v[1], (float)v[4], (float)v[7]);
            var c2 = Vector3.Cross(c0, c1); // guarantees a proper rotation (det +1)
            axes = FromMatrix(new Mat3(c0, c1, Vector3.Normalize(c2)));
            return new Vector3((float)a[0], (float)a[4], (float)a[8]);
        }

        /// <summary>The unit quaternion of a rotation matrix (Shepperd's method, stable for every angle).</summary>
        public static Quaternion FromMatrix(in Mat3 r)
        {
            float m00 = r.C0.X, m11 = r.C1.Y, m22 = r.C2.Z;
            float trace = m00 + m11 + m22;
            Quaternion q;
            if (trace > 0)
            {
                float s = MathF.Sqrt(trace + 1f) * 2f;
                q = new Quaternion((r.C1.Z - r.C2.Y) / s, (r.C2.X - r.C0.Z) / s, (r.C0.Y - r.C1.X) / s, 0.25f * s);
            }
            else if (m00 > m11 && m00 > m22)
            {
                float s = MathF.Sqrt(1f + m00 - m11 - m22) * 2f;
                q = new Quaternion(0.25f * s, (r.C1.X + r.C0.Y) / s, (r.C2.X + r.C0.Z) / s, (r.C1.Z - r.C2.Y) / s);
            }
            else if (m11 > m22)
            {
                float s = MathF.Sqrt(1f + m11 - m00 - m22) * 2f;
                q = new Quaternion((r.C1.X + r.C0.Y) / s, 0.25f * s, (r.C2.Y + r.C1.Z) / s, (r.C2.X - r.C0.Z) / s);
            }
            else
            {
                float s = MathF.Sqrt(1f + m22 - m00 - m11) * 2f;
                q = new Quaternion((r.C2.X + r.C0.Z) / s, (r.C2.Y + r.C1.Z) / s, 0.25f * s, (r.C0.Y - r.C1.X) / s);
            }
            return Quaternion.Normalize(q);
        }
    }
}
