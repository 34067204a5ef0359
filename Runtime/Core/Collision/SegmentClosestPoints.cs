using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Closest points of two segments p1-q1 and p2-q2 (Ericson, Real-Time Collision
    /// Detection, 5.1.9): minimise |(p1 + s d1) - (p2 + t d2)|^2 over s, t in [0, 1], clamping
    /// s, recomputing t, and clamping again. Degenerate (point) segments are handled.
    /// </summary>
    internal static class SegmentClosestPoints
    {
        public static void Compute(Vector3 p1, Vector3 q1, Vector3 p2, Vector3 q2, out float s, out float t, out Vector3 c1, out Vector3 c2)
        {
            Vector3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
            float a = Vector3.Dot(d1, d1), e = Vector3.Dot(d2, d2), f = Vector3.Dot(d2, r);
            const float eps = 1e-12f;
            if (a <= eps && e <= eps)
            {
                s = t = 0;
            }
            else if (a <= eps)
            {
                s = 0;
                t = Clamp01(f / e);
            }
            else
            {
                float c = Vector3.Dot(d1, r);
                if (e <= eps)
                {
                    t = 0;
                    s = Clamp01(-c / a);
                }
                else
                {
                    float b = Vector3.Dot(d1, d2);
                    float denom = a * e - b * b;
                    // Parallel segments (denom 0): any s works; 0 is as good as any.
                    s = denom > eps * a * e ? Clamp01((b * f - c * e) / denom) : 0;
                    t = (b * s + f) / e;
                    if (t < 0)
                    {
                        t = 0;
                        s = Clamp01(-c / a);
                    }
                    else if (t > 1)
                    {
                        t = 1;
                        s = Clamp01((b - c) / a);
                    }
                }
            }
            c1 = p1 + d1 * s;
            c2 = p2 + d2 * t;
        }

        /// <summary>The point of segment p-q closest to x, and its parameter.</summary>
        public static Vector3 OnSegment(Vector3 p, Vector3 q, Vector3 x, out float t)
        {
            Vector3 d = q - p;
            float dd = d.LengthSquared();
            t = dd > 1e-12f ? Clamp01(Vector3.Dot(x - p, d) / dd) : 0;
            return p + d * t;
        }

        static float Clamp01(float x) => x < 0 ? 0 : x > 1 ? 1 : x;
    }
}
