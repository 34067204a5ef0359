#if NET
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// <see cref="TorqueFree"/> for eight tets at once: the same operations in the same order,
    /// lane by lane, so each lane's result is bit-identical to the scalar projection.
    /// </summary>
    internal static class TorqueFreeWide
    {
        /// <summary>
        /// Adjusts the impulses g_k of the lanes set in <paramref name="apply"/> (a comparison
        /// mask); lanes whose inertia is singular are left as they are, as in the scalar form.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Project(in Lanes8 p0, in Lanes8 p1, in Lanes8 p2, in Lanes8 p3,
            Vector256<float> m0, Vector256<float> m1, Vector256<float> m2, Vector256<float> m3, Vector256<float> apply,
            ref Lanes8 g0, ref Lanes8 g1, ref Lanes8 g2, ref Lanes8 g3)
        {
            Vector256<float> invTotal = Vector256<float>.One / (m0 + m1 + m2 + m3);
            Lanes8 c = (m0 * p0 + m1 * p1 + m2 * p2 + m3 * p3) * invTotal;
            Lanes8 r0 = p0 - c, r1 = p1 - c, r2 = p2 - c, r3 = p3 - c;
            Lanes8 torque = Lanes8.Cross(r0, g0) + Lanes8.Cross(r1, g1) + Lanes8.Cross(r2, g2) + Lanes8.Cross(r3, g3);
            Lanes8 q0 = m0 * r0, q1 = m1 * r1, q2 = m2 * r2, q3 = m3 * r3;
            Lanes8 diag = q0 * r0 + q1 * r1 + q2 * r2 + q3 * r3;
            Vector256<float> offX = q0.X * r0.Y + q1.X * r1.Y + q2.X * r2.Y + q3.X * r3.Y;
            Vector256<float> offY = q0.Y * r0.Z + q1.Y * r1.Z + q2.Y * r2.Z + q3.Y * r3.Z;
            Vector256<float> offZ = q0.Z * r0.X + q1.Z * r1.X + q2.Z * r2.X + q3.Z * r3.X;

            // TorqueFree.Solve, lane by lane.
            Vector256<float> a = diag.Y + diag.Z, b = diag.X + diag.Z, cc0 = diag.X + diag.Y;
            Vector256<float> d = -offX, f = -offY, e = -offZ;
            Vector256<float> ca = b * cc0 - f * f, cb = a * cc0 - e * e, cc = a * b - d * d;
            Vector256<float> cd = e * f - d * cc0, ce = d * f - b * e, cf = d * e - a * f;
            Vector256<float> det = a * ca + d * cd + e * ce;
            Vector256<float> scale = a + b + cc0;
            Vector256<float> ok = Vector256.GreaterThan(det, Vector256.Create(1e-9f) * scale * scale * scale) & apply;
            if (ok.ExtractMostSignificantBits() == 0) return;
            Vector256<float> inv = Vector256<float>.One / det;
            var omega = new Lanes8(
                (ca * torque.X + cd * torque.Y + ce * torque.Z) * inv,
                (cd * torque.X + cb * torque.Y + cf * torque.Z) * inv,
                (ce * torque.X + cf * torque.Y + cc * torque.Z) * inv);
            if (ok.ExtractMostSignificantBits() == 0xFF)
            {
                g0 -= Lanes8.Cross(omega, q0);
                g1 -= Lanes8.Cross(omega, q1);
                g2 -= Lanes8.Cross(omega, q2);
                g3 -= Lanes8.Cross(omega, q3);
                return;
            }
            g0 = Lanes8.Select(ok, g0 - Lanes8.Cross(omega, q0), g0);
            g1 = Lanes8.Select(ok, g1 - Lanes8.Cross(omega, q1), g1);
            g2 = Lanes8.Select(ok, g2 - Lanes8.Cross(omega, q2), g2);
            g3 = Lanes8.Select(ok, g3 - Lanes8.Cross(omega, q3), g3);
        }
    }
}
#endif
