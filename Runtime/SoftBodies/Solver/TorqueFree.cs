using System.Numerics;
using System.Runtime.CompilerServices;

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
        /// <summary>Adjusts the impulses g_k (= m_k dx_k) of a 4-vertex element of (finite) masses m_k.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Project(Vector3 p0, Vector3 p1, Vector3 p2, Vector3 p3, float m0, float m1, float m2, float m3,
            ref Vector3 g0, ref Vector3 g1, ref Vector3 g2, ref Vector3 g3)
        {
            Vector3 c = (m0 * p0 + m1 * p1 + m2 * p2 + m3 * p3) * (1f / (m0 + m1 + m2 + m3));
            Vector3 r0 = p0 - c, r1 = p1 - c, r2 = p2 - c, r3 = p3 - c;
            Vector3 torque = Vector3.Cross(r0, g0) + Vector3.Cross(r1, g1) + Vector3.Cross(r2, g2) + Vector3.Cross(r3, g3);
            Vector3 q0 = m0 * r0, q1 = m1 * r1, q2 = m2 * r2, q3 = m3 * r3;
            // Second moments sum m r r^T: diagonal and off-diagonal.
            Vector3 diag = q0 * r0 + q1 * r1 + q2 * r2 + q3 * r3;
            Vector3 off = q0 * new Vector3(r0.Y, r0.Z, r0.X) + q1 * new Vector3(r1.Y, r1.Z, r1.X)
                + q2 * new Vector3(r2.Y, r2.Z, r2.X) + q3 * new Vector3(r3.Y, r3.Z, r3.X);
            if (!Solve(diag, off, torque, out Vector3 omega)) return;
            g0 -= Vector3.Cross(omega, q0);
            g1 -= Vector3.Cross(omega, q1);
            g2 -= Vector3.Cross(omega, q2);
            g3 -= Vector3.Cross(omega, q3);
        }

        /// <summary>
        /// <see cref="Project(Vector3, Vector3, Vector3, Vector3, float, float, float, float, ref Vector3, ref Vector3, ref Vector3, ref Vector3)"/>
        /// about the positions <paramref name="about"/> of vertices a, b, c, d, where all four are free
        /// (<paramref name="free"/> &gt; 0); an element with a pinned or attached vertex keeps its
        /// impulses, as the rigid rotation would move the fixed vertex.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void ProjectIfFree(int a, int b, int c, int d, Vector3[] about, float[] m, float[] free,
            ref Vector3 g0, ref Vector3 g1, ref Vector3 g2, ref Vector3 g3)
        {
            if (free[a] > 0f && free[b] > 0f && free[c] > 0f && free[d] > 0f)
                Project(about[a], about[b], about[c], about[d], m[a], m[b], m[c], m[d], ref g0, ref g1, ref g2, ref g3);
        }

        /// <summary>The same for a triangle (3 vertices).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Project(Vector3 p0, Vector3 p1, Vector3 p2, float m0, float m1, float m2,
            ref Vector3 g0, ref Vector3 g1, ref Vector3 g2)
        {
            Vector3 c = (m0 * p0 + m1 * p1 + m2 * p2) / (m0 + m1 + m2);
            Vector3 r0 = p0 - c, r1 = p1 - c, r2 = p2 - c;
            Vector3 torque = Vector3.Cross(r0, g0) + Vector3.Cross(r1, g1) + Vector3.Cross(r2, g2);
            Vector3 q0 = m0 * r0, q1 = m1 * r1, q2 = m2 * r2;
            Vector3 diag = q0 * r0 + q1 * r1 + q2 * r2;
            Vector3 off = q0 * new Vector3(r0.Y, r0.Z, r0.X) + q1 * new Vector3(r1.Y, r1.Z, r1.X) + q2 * new Vector3(r2.Y, r2.Z, r2.X);
            if (!Solve(diag, off, torque, out Vector3 omega)) return;
            g0 -= Vector3.Cross(omega, q0);
            g1 -= Vector3.Cross(omega, q1);
            g2 -= Vector3.Cross(omega, q2);
        }

        /// <summary>The same for a triangle a, b, c.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void ProjectIfFree(int a, int b, int c, Vector3[] about, float[] m, float[] free,
            ref Vector3 g0, ref Vector3 g1, ref Vector3 g2)
        {
            if (free[a] > 0f && free[b] > 0f && free[c] > 0f)
                Project(about[a], about[b], about[c], m[a], m[b], m[c], ref g0, ref g1, ref g2);
        }

        // Solves I omega = torque for the inertia I = tr(S) 1 - S of the second moments S
        // (diag = (Sxx, Syy, Szz), off = (Sxy, Syz, Szx)) by the adjugate of the symmetric I.
        // I is singular only when the points are collinear; the correction is then skipped
        // (such an element has collapsed and its gradient is degenerate anyway).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static bool Solve(Vector3 diag, Vector3 off, Vector3 torque, out Vector3 omega)
        {
            float a = diag.Y + diag.Z, b = diag.X + diag.Z, c = diag.X + diag.Y;
            float d = -off.X, f = -off.Y, e = -off.Z; // Ixy, Iyz, Ixz
            float ca = b * c - f * f, cb = a * c - e * e, cc = a * b - d * d;
            float cd = e * f - d * c, ce = d * f - b * e, cf = d * e - a * f;
            float det = a * ca + d * cd + e * ce;
            float scale = a + b + c;
            if (!(det > 1e-9f * scale * scale * scale))
            {
                omega = default;
                return false;
            }
            float inv = 1f / det;
            omega = new Vector3(
                ca * torque.X + cd * torque.Y + ce * torque.Z,
                cd * torque.X + cb * torque.Y + cf * torque.Z,
                ce * torque.X + cf * torque.Y + cc * torque.Z) * inv;
            return true;
        }
    }
}
