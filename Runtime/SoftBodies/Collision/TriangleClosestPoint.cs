using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The point of a triangle closest to a query point, with its barycentric weights, by the
    /// Voronoi-region walk of Ericson, "Real-Time Collision Detection" (2005), section 5.1.5:
    /// vertex regions first, then edge regions, else the projection onto the face.
    /// </summary>
    internal static class TriangleClosestPoint
    {
        /// <summary>The closest point of triangle (a, b, c) to <paramref name="p"/>; it equals wa a + wb b + wc c with the weights in <paramref name="weights"/>.</summary>
        public static Vector3 Find(Vector3 p, Vector3 a, Vector3 b, Vector3 c, out Vector3 weights)
        {
            Vector3 ab = b - a, ac = c - a, ap = p - a;
            float d1 = Vector3.Dot(ab, ap), d2 = Vector3.Dot(ac, ap);
            if (d1 <= 0f && d2 <= 0f) { weights = new Vector3(1, 0, 0); return a; }

            Vector3 bp = p - b;
            float d3 = Vector3.Dot(ab, bp), d4 = Vector3.Dot(ac, bp);
            if (d3 >= 0f && d4 <= d3) { weights = new Vector3(0, 1, 0); return b; }

            float vc = d1 * d4 - d3 * d2;
            if (vc <= 0f && d1 >= 0f && d3 <= 0f)
            {
                float t = d1 / (d1 - d3);
                weights = new Vector3(1 - t, t, 0);
                return a + t * ab;
            }

            Vector3 cp = p - c;
            float d5 = Vector3.Dot(ab, cp), d6 = Vector3.Dot(ac, cp);
            if (d6 >= 0f && d5 <= d6) { weights = new Vector3(0, 0, 1); return c; }

            float vb = d5 * d2 - d1 * d6;
            if (vb <= 0f && d2 >= 0f && d6 <= 0f)
            {
                float t = d2 / (d2 - d6);
                weights = new Vector3(1 - t, 0, t);
                return a + t * ac;
            }

            float va = d3 * d6 - d5 * d4;
            if (va <= 0f && d4 - d3 >= 0f && d5 - d6 >= 0f)
            {
                float t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
                weights = new Vector3(0, 1 - t, t);
                return b + t * (c - b);
            }

            float denominator = 1f / (va + vb + vc);
            float v = vb * denominator, w = vc * denominator;
            weights = new Vector3(1 - v - w, v, w);
            return a + v * ab + w * ac;
        }
    }
}
