using System;
using System.Numerics;
using Fulcrum.SoftBodies;

namespace Fulcrum.Tests.SoftScenes
{
    /// <summary>How far apart two soft solids' surfaces are: negative when a vertex of one lies inside the other.</summary>
    static class SoftGap
    {
        /// <summary>
        /// The smallest signed distance from a surface vertex of either body to the other's surface:
        /// the distance to the nearest surface triangle, negated when the vertex is inside one of
        /// the other body's tetrahedra. Brute force; for scene tests with a few hundred vertices.
        /// </summary>
        public static float Min(SoftBody a, SoftBody b) => MathF.Min(OneWay(a, b), OneWay(b, a));

        static float OneWay(SoftBody from, SoftBody to)
        {
            ReadOnlySpan<int> surface = from.Mesh.SurfaceTriangles;
            ReadOnlySpan<Vector3> x = from.Positions;
            var seen = new bool[x.Length];
            float best = float.MaxValue;
            for (int t = 0; t < surface.Length; t++)
            {
                int i = surface[t];
                if (seen[i]) continue;
                seen[i] = true;
                best = MathF.Min(best, SignedDistance(x[i], to));
            }
            return best;
        }

        public static float SignedDistance(Vector3 p, SoftBody body)
        {
            ReadOnlySpan<int> tris = body.Mesh.SurfaceTriangles;
            ReadOnlySpan<Vector3> y = body.Positions;
            float d2 = float.MaxValue;
            for (int t = 0; t < tris.Length; t += 3)
            {
                Vector3 q = Fulcrum.SoftBodies.TriangleClosestPoint.Find(p, y[tris[t]], y[tris[t + 1]], y[tris[t + 2]], out _);
                d2 = MathF.Min(d2, (p - q).LengthSquared());
            }
            float d = MathF.Sqrt(d2);
            return Inside(p, body) ? -d : d;
        }

        static bool Inside(Vector3 p, SoftBody body)
        {
            ReadOnlySpan<int> tets = body.Mesh.Tetrahedra;
            ReadOnlySpan<Vector3> y = body.Positions;
            for (int t = 0; t < tets.Length; t += 4)
            {
                Vector3 a = y[tets[t]], e1 = y[tets[t + 1]] - a, e2 = y[tets[t + 2]] - a, e3 = y[tets[t + 3]] - a, r = p - a;
                float det = Vector3.Dot(e1, Vector3.Cross(e2, e3));
                if (MathF.Abs(det) < 1e-12f) continue;
                float u = Vector3.Dot(r, Vector3.Cross(e2, e3)) / det;
                float v = Vector3.Dot(e1, Vector3.Cross(r, e3)) / det;
                float w = Vector3.Dot(e1, Vector3.Cross(e2, r)) / det;
                if (u > 0 && v > 0 && w > 0 && u + v + w < 1) return true;
            }
            return false;
        }
    }
}
