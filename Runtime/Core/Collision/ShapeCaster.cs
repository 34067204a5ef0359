using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A convex shape translated along a segment against one shape: the first fraction of the
    /// motion at which they touch, by conservative advancement (Mirtich, "Impulse-based
    /// dynamic simulation of rigid body systems", 1996): the GJK distance d between them can
    /// shrink by at most |motion| per unit fraction, so advancing by d / |motion| never passes
    /// the contact. Shapes touching or overlapping at the start are not reported.
    /// </summary>
    internal static class ShapeCaster
    {
        const int MaxIterations = 64;

        /// <summary>Target gap at which the cast counts as touching, metres.</summary>
        public const float Tolerance = 1e-4f;

        /// <summary>The cast shape <paramref name="a"/> moved by <paramref name="motion"/> against the core shape <paramref name="b"/>.</summary>
        public static bool Cast(in SupportShape a, Vector3 motion, in SupportShape b, float targetGap, out float fraction, out Vector3 normal, out Vector3 point)
        {
            fraction = 0;
            normal = default;
            point = default;
            float length = motion.Length();
            if (!(length > 0)) return false;
            float radii = a.Radius + b.Radius;
            SupportShape moved = a;
            float t = 0;
            for (int iteration = 0; iteration < MaxIterations; iteration++)
            {
                Translate(a, motion * t, ref moved);
                float dist = Gjk.Distance(moved, b, out Vector3 pa, out Vector3 pb, out _) - radii;
                if (dist <= targetGap + Tolerance)
                {
                    if (iteration == 0) return false;
                    Vector3 ab = pb - pa;
                    float len = ab.Length();
                    Vector3 n = len > 1e-9f ? ab / len : -motion / length;
                    fraction = t;
                    normal = -n;
                    point = pb - n * b.Radius;
                    return true;
                }
                if (iteration == 0)
                {
                    // Moving apart along the closing direction: never touches.
                    Vector3 ab = pb - pa;
                    if (Vector3.Dot(ab, motion) <= 0 && ab.LengthSquared() > 1e-12f) return false;
                }
                t += (dist - targetGap) / length;
                if (t > 1) return false;
            }
            return false;
        }

        /// <summary>A copy of <paramref name="s"/> moved by <paramref name="offset"/>.</summary>
        public static void Translate(in SupportShape s, Vector3 offset, ref SupportShape into)
        {
            into = s;
            into.Center += offset;
            into.A += offset;
            into.B += offset;
            into.C += offset;
        }

        /// <summary>The cast against a half-space n . x &lt;= offset: exact.</summary>
        public static bool CastPlane(in SupportShape a, Vector3 motion, Vector3 n, float offset, float targetGap, out float fraction, out Vector3 point)
        {
            fraction = 0;
            point = default;
            Vector3 deepest = a.Support(-n, out _) - n * a.Radius;
            float gap = Vector3.Dot(n, deepest) - offset - targetGap;
            float rate = -Vector3.Dot(n, motion);
            if (gap <= 0 || rate <= 0) return false;
            fraction = gap / rate;
            if (fraction > 1) return false;
            point = deepest + motion * fraction - n * targetGap;
            return true;
        }
    }
}
