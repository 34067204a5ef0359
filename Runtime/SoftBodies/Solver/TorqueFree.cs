using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Makes one element's position correction free of net angular impulse. A substep's
    /// velocity is (x - x_prev) / h, so the angular momentum it ends with is
    /// sum m x_prev x v: a correction m dx = g changes it by sum x_prev x g / h. The gradients of
    /// a rotation-invariant constraint satisfy sum x x g = 0 at the iterate x they were taken at,
    /// not at x_prev; with one Gauss-Seidel iteration the iterate of a later element has already
    /// moved, and each element then leaves a torque (the 3x stretched block span up to
    /// 1.5 kg m^2/s from rest). Removing, per element, the rigid rotation about its x_prev centre
    /// of mass that carries that torque keeps sum m dx = 0 and makes sum x_prev x g = 0 exactly;
    /// a converged solve is changed only at O(h |v| / size).
    /// </summary>
    internal static class TorqueFree
    {
        /// <summary>Adjusts the impulses g_k (= m_k dx_k) of a 4-vertex element; all inverse masses must be positive.</summary>
        public static void Project(Vector3 p0, Vector3 p1, Vector3 p2, Vector3 p3, float w0, float w1, float w2, float w3,
            ref Vector3 g0, ref Vector3 g1, ref Vector3 g2, ref Vector3 g3)
        {
            float m0 = 1f / w0, m1 = 1f / w1, m2 = 1f / w2, m3 = 1f / w3;
            Vector3 c = (m0 * p0 + m1 * p1 + m2 * p2 + m3 * p3) / (m0 + m1 + m2 + m3);
            Vector3 r0 = p0 - c, r1 = p1 - c, r2 = p2 - c, r3 = p3 - c;
            Vector3 torque = Vector3.Cross(r0, g0) + Vector3.Cross(r1, g1) + Vector3.Cross(r2, g2) + Vector3.Cross(r3, g3);
            if (!Solve(Inertia(m0, r0) + Inertia(m1, r1) + Inertia(m2, r2) + Inertia(m3, r3), torque, out Vector3 omega)) return;
            g0 -= m0 * Vector3.Cross(omega, r0);
            g1 -= m1 * Vector3.Cross(omega, r1);
            g2 -= m2 * Vector3.Cross(omega, r2);
            g3 -= m3 * Vector3.Cross(omega, r3);
        }

        /// <summary>The same for a triangle (3 vertices).</summary>
        public static void Project(Vector3 p0, Vector3 p1, Vector3 p2, float w0, float w1, float w2,
            ref Vector3 g0, ref Vector3 g1, ref Vector3 g2)
        {
            float m0 = 1f / w0, m1 = 1f / w1, m2 = 1f / w2;
            Vector3 c = (m0 * p0 + m1 * p1 + m2 * p2) / (m0 + m1 + m2);
            Vector3 r0 = p0 - c, r1 = p1 - c, r2 = p2 - c;
            Vector3 torque = Vector3.Cross(r0, g0) + Vector3.Cross(r1, g1) + Vector3.Cross(r2, g2);
            if (!Solve(Inertia(m0, r0) + Inertia(m1, r1) + Inertia(m2, r2), torque, out Vector3 omega)) return;
            g0 -= m0 * Vector3.Cross(omega, r0);
            g1 -= m1 * Vector3.Cross(omega, r1);
            g2 -= m2 * Vector3.Cross(omega, r2);
        }

        // m (|r|^2 I - r r^T): the point's inertia about the centre.
        static Mat3 Inertia(float m, Vector3 r)
        {
            float xx = m * r.X * r.X, yy = m * r.Y * r.Y, zz = m * r.Z * r.Z;
            float xy = -m * r.X * r.Y, xz = -m * r.X * r.Z, yz = -m * r.Y * r.Z;
            return new Mat3(new Vector3(yy + zz, xy, xz), new Vector3(xy, xx + zz, yz), new Vector3(xz, yz, xx + yy));
        }

        // The inertia of 3 or 4 points is singular only when they are collinear; the correction
        // is then skipped (such an element has collapsed and its gradient is degenerate anyway).
        static bool Solve(in Mat3 inertia, Vector3 torque, out Vector3 omega)
        {
            float det = inertia.Determinant;
            float scale = inertia.C0.X + inertia.C1.Y + inertia.C2.Z;
            if (!(det > 1e-9f * scale * scale * scale))
            {
                omega = default;
                return false;
            }
            omega = inertia.Inverse() * torque;
            return true;
        }
    }
}
