using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The signed dihedral angle of two triangles (A, C, D) and (B, D, C) hinged on the edge
    /// C-D: the angle from the normal of the first to the normal of the second about the edge
    /// direction e = x_D - x_C; 0 when flat. Its gradient is the hinge formula of Bridson,
    /// Marino and Fedkiw 2003 ("Simulation of clothing with folds and wrinkles", section 4):
    /// a wing moves the angle by 1/height along minus its triangle's normal, and the edge
    /// vertices take the balance in proportion to where the wings project onto the edge.
    /// </summary>
    internal static class DihedralAngle
    {
        public static float Of(Vector3 a, Vector3 b, Vector3 c, Vector3 d)
        {
            Vector3 nA = Vector3.Cross(c - a, d - a), nB = Vector3.Cross(d - b, c - b);
            Vector3 e = d - c;
            float el = e.Length();
            if (el < 1e-12f) return 0f;
            float sin = Vector3.Dot(Vector3.Cross(nA, nB), e) / el;
            float cos = Vector3.Dot(nA, nB);
            return MathF.Atan2(sin, cos);
        }

        /// <summary>The angle and its gradient; false when a triangle or the edge is degenerate.</summary>
        public static bool WithGradient(Vector3 a, Vector3 b, Vector3 c, Vector3 d, out float angle,
            out Vector3 gA, out Vector3 gB, out Vector3 gC, out Vector3 gD)
        {
            Vector3 nA = Vector3.Cross(c - a, d - a), nB = Vector3.Cross(d - b, c - b);
            Vector3 e = d - c;
            float el = e.Length();
            float lA = nA.LengthSquared(), lB = nB.LengthSquared();
            if (el < 1e-12f || lA < 1e-24f || lB < 1e-24f)
            {
                angle = 0f;
                gA = gB = gC = gD = Vector3.Zero;
                return false;
            }
            angle = MathF.Atan2(Vector3.Dot(Vector3.Cross(nA, nB), e) / el, Vector3.Dot(nA, nB));
            Vector3 uA = nA / lA, uB = nB / lB;
            float invEl = 1f / el;
            gA = -el * uA;
            gB = -el * uB;
            gC = -(Vector3.Dot(a - d, e) * invEl * uA + Vector3.Dot(b - d, e) * invEl * uB);
            gD = Vector3.Dot(a - c, e) * invEl * uA + Vector3.Dot(b - c, e) * invEl * uB;
            return true;
        }
    }
}
