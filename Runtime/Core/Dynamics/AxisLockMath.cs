using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The arithmetic of <see cref="AxisLocks"/>: masks of the free world axes, the projected
    /// inverse inertia P I^-1 P, and the inverses of effective-mass matrices that the locks
    /// make singular. Only called for bodies with locks: unlocked bodies never reach it.
    /// </summary>
    internal static class AxisLockMath
    {
        /// <summary>1 on the free translation axes, 0 on the locked ones.</summary>
        public static Vector3 LinearMask(AxisLocks locks) => new Vector3(
            (locks & AxisLocks.LinearX) != 0 ? 0f : 1f,
            (locks & AxisLocks.LinearY) != 0 ? 0f : 1f,
            (locks & AxisLocks.LinearZ) != 0 ? 0f : 1f);

        /// <summary>1 on the free rotation axes, 0 on the locked ones.</summary>
        public static Vector3 AngularMask(AxisLocks locks) => new Vector3(
            (locks & AxisLocks.AngularX) != 0 ? 0f : 1f,
            (locks & AxisLocks.AngularY) != 0 ? 0f : 1f,
            (locks & AxisLocks.AngularZ) != 0 ? 0f : 1f);

        /// <summary>
        /// d . M^-1 d for a per-axis inverse mass M^-1 = diag(<paramref name="perAxis"/>) and a unit
        /// direction d: the inverse mass a row along d sees. A body without locks (three equal
        /// components) gives its scalar inverse mass unchanged, bit for bit.
        /// </summary>
        public static float InverseMassAlong(Vector3 perAxis, Vector3 d) =>
            perAxis.X == perAxis.Y && perAxis.Y == perAxis.Z ? perAxis.X : Vector3.Dot(perAxis, d * d);

        /// <summary>Zeroes the components of a velocity along the locked translation axes.</summary>
        public static Vector3 MaskLinear(Vector3 v, AxisLocks locks)
        {
            if ((locks & AxisLocks.LinearX) != 0) v.X = 0;
            if ((locks & AxisLocks.LinearY) != 0) v.Y = 0;
            if ((locks & AxisLocks.LinearZ) != 0) v.Z = 0;
            return v;
        }

        /// <summary>Zeroes the components of an angular velocity about the locked rotation axes.</summary>
        public static Vector3 MaskAngular(Vector3 w, AxisLocks locks)
        {
            if ((locks & AxisLocks.AngularX) != 0) w.X = 0;
            if ((locks & AxisLocks.AngularY) != 0) w.Y = 0;
            if ((locks & AxisLocks.AngularZ) != 0) w.Z = 0;
            return w;
        }

        /// <summary>
        /// P I^-1 P, P = diag(free rotation axes): the rows and columns of the locked axes of a
        /// world inverse inertia zeroed (Jolt's MotionProperties::GetInverseInertiaForRotation).
        /// </summary>
        public static Mat3 ProjectInertia(in Mat3 inverseInertia, AxisLocks locks)
        {
            Vector3 p = AngularMask(locks);
            // (P A P)_ij = p_i A_ij p_j: each column j scaled by p_j, each row i by p_i.
            return new Mat3(p * (p.X * inverseInertia.C0), p * (p.Y * inverseInertia.C1), p * (p.Z * inverseInertia.C2));
        }

        /// <summary>
        /// The inverse of a symmetric positive semi-definite matrix whose null space is spanned
        /// by world axes (a sum of projected inverse inertias, or per-axis inverse masses): a
        /// zero diagonal entry means a zero row and column (semi-definiteness), so that axis is
        /// set aside (1 on the diagonal while inverting, 0 in the result) and the rest, which
        /// is definite, is inverted. The pseudo-inverse: no impulse along a direction nothing can move.
        /// </summary>
        public static Mat3 InverseOnFreeAxes(in Mat3 m)
        {
            Mat3 k = m;
            bool x = k.C0.X == 0, y = k.C1.Y == 0, z = k.C2.Z == 0;
            if (x) k.C0.X = 1;
            if (y) k.C1.Y = 1;
            if (z) k.C2.Z = 1;
            Mat3 inv = k.Inverse();
            if (x) { inv.C0 = Vector3.Zero; inv.C1.X = 0; inv.C2.X = 0; }
            if (y) { inv.C1 = Vector3.Zero; inv.C0.Y = 0; inv.C2.Y = 0; }
            if (z) { inv.C2 = Vector3.Zero; inv.C0.Z = 0; inv.C1.Z = 0; }
            return inv;
        }

        /// <summary>
        /// The pseudo-inverse of a symmetric positive semi-definite 3x3 matrix by its
        /// eigen-decomposition (K = R diag(l) R^T, K^+ = R diag(1/l, 0 where l is negligible) R^T).
        /// The point constraint of a joint on a locked body is singular along directions the
        /// anchors cannot move apart in, which need not be world axes (a body turning only about
        /// z, held by an anchor off its centre); the plain inverse would give up on the whole
        /// joint, the pseudo-inverse leaves out only what cannot be satisfied.
        /// </summary>
        public static Mat3 PseudoInverse(in Mat3 k)
        {
            Vector3 l = Rotation.Diagonalize(k, out Quaternion axes);
            float largest = MathF.Max(MathF.Abs(l.X), MathF.Max(MathF.Abs(l.Y), MathF.Abs(l.Z)));
            if (!(largest > 0) || !float.IsFinite(largest)) return Mat3.Zero;
            float eps = 1e-6f * largest;
            var inv = new Vector3(l.X > eps ? 1f / l.X : 0, l.Y > eps ? 1f / l.Y : 0, l.Z > eps ? 1f / l.Z : 0);
            return Mat3.RotateDiagonal(Mat3.FromQuaternion(axes), inv);
        }
    }
}
