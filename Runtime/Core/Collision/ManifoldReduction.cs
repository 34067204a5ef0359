using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Keeps four of many contact points so that their polygon covers as much of the contact
    /// area as possible (Gregorius, "Robust contact creation for physics simulations", GDC
    /// 2015): the deepest point (so penetration is always seen), the point farthest from it,
    /// the point making the largest triangle with those two, and the point farthest outside
    /// that triangle. Areas are measured in the contact plane.
    /// </summary>
    internal static class ManifoldReduction
    {
        /// <summary>
        /// Reorders points [start, start + count) so the kept ones come first; returns how
        /// many are kept (at most <see cref="ContactManifold.MaxPoints"/>). Points that add no
        /// area (on the segment of two others, inside the triangle of three) are dropped too.
        /// </summary>
        public static int Reduce(Vector3[] position, float[] separation, uint[] id, int start, int count, Vector3 normal)
        {
            if (count <= 2) return count;
            int end = start + count;

            int a = start;
            for (int i = start + 1; i < end; i++)
                if (separation[i] < separation[a]) a = i;

            int b = -1;
            float best = -1;
            for (int i = start; i < end; i++)
            {
                Vector3 d = position[i] - position[a];
                d -= Vector3.Dot(d, normal) * normal;
                float l = d.LengthSquared();
                if (l > best) { best = l; b = i; }
            }
            float bestLength = best;

            int c = -1;
            best = -1;
            float side = 1;
            for (int i = start; i < end; i++)
            {
                float area = Vector3.Dot(Vector3.Cross(position[b] - position[a], position[i] - position[a]), normal);
                if (MathF.Abs(area) > best) { best = MathF.Abs(area); c = i; side = area >= 0 ? 1 : -1; }
            }

            // The fourth point: the one farthest outside the triangle (a, b, c), measured by the
            // most negative signed area against the triangle's edges taken counter-clockwise.
            int d4 = -1;
            // A third point must stand off the line a-b by more than 1e-4 of its length.
            bool flat = !(best > 1e-4f * bestLength);
            if (!flat)
            {
                Vector3 pa = position[a], pb = position[b], pc = position[c];
                if (side < 0) (pb, pc) = (pc, pb);
                float most = -1e-4f * bestLength;
                for (int i = start; i < end; i++)
                {
                    if (i == a || i == b || i == c) continue;
                    Vector3 q = position[i];
                    float s = MathF.Min(SignedArea(pa, pb, q, normal), MathF.Min(SignedArea(pb, pc, q, normal), SignedArea(pc, pa, q, normal)));
                    if (s < most) { most = s; d4 = i; }
                }
            }

            int kept = 0;
            Span<int> chosen = stackalloc int[4];
            chosen[kept++] = a;
            if (b != a) chosen[kept++] = b;
            if (c >= 0 && c != a && c != b && !flat) chosen[kept++] = c;
            if (d4 >= 0) chosen[kept++] = d4;
            for (int i = 1; i < kept; i++)
                for (int j = i; j > 0 && chosen[j - 1] > chosen[j]; j--)
                    (chosen[j - 1], chosen[j]) = (chosen[j], chosen[j - 1]);
            for (int k = 0; k < kept; k++)
            {
                int from = chosen[k], to = start + k;
                if (from == to) continue;
                position[to] = position[from];
                separation[to] = separation[from];
                id[to] = id[from];
            }
            return kept;
        }

        static float SignedArea(Vector3 p, Vector3 q, Vector3 r, Vector3 n) =>
            Vector3.Dot(Vector3.Cross(q - p, r - p), n);
    }
}
