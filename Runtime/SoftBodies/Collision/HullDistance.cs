using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Signed distance from a point to a convex hull, in the hull's frame, from its face planes:
    /// inside, the least-deep face plane is the nearest surface (exact for a convex solid), so
    /// the distance is that plane's (negative) height and the normal its normal; outside, the
    /// nearest point lies on one of the faces the point sees (positive height), found by
    /// projecting onto each such face and falling back to its edges when the projection
    /// leaves the polygon.
    /// </summary>
    internal static class HullDistance
    {
        /// <summary>True when <paramref name="p"/> is inside the hull or closer than <paramref name="radius"/> to it.</summary>
        public static bool Query(ConvexHull hull, Vector3 p, float radius, out float distance, out Vector3 normal)
        {
            Vector3[] normals = hull.FaceNormals;
            float[] offsets = hull.FaceOffsets;
            int deepest = 0;
            float highest = float.MinValue;
            for (int f = 0; f < normals.Length; f++)
            {
                float s = Vector3.Dot(normals[f], p) - offsets[f];
                if (s > highest) { highest = s; deepest = f; }
            }
            // Every face height is a lower bound on the distance outside.
            if (highest >= radius)
            {
                distance = float.MaxValue;
                normal = Vector3.Zero;
                return false;
            }
            if (highest <= 0f)
            {
                distance = highest;
                normal = normals[deepest];
                return true;
            }

            float best2 = float.MaxValue;
            Vector3 closest = p;
            for (int f = 0; f < normals.Length; f++)
            {
                float s = Vector3.Dot(normals[f], p) - offsets[f];
                if (s <= 0f) continue;
                Vector3 q = ClosestOnFace(hull, f, p - s * normals[f], s);
                float d2 = (p - q).LengthSquared();
                if (d2 < best2) { best2 = d2; closest = q; }
            }
            float d = MathF.Sqrt(best2);
            if (d >= radius)
            {
                distance = d;
                normal = Vector3.Zero;
                return false;
            }
            distance = d;
            normal = d > 1e-9f ? (p - closest) / d : normals[deepest];
            return true;
        }

        /// <summary>The closest point of face <paramref name="f"/> to a point whose projection on the face plane is <paramref name="projected"/>.</summary>
        static Vector3 ClosestOnFace(ConvexHull hull, int f, Vector3 projected, float height)
        {
            Vector3 n = hull.FaceNormals[f];
            Vector3[] v = hull.Vertices;
            int start = hull.FaceStart[f], end = hull.FaceStart[f + 1];
            int count = end - start;
            // Inside the polygon when the projection is on the same side of every edge (either winding).
            int positive = 0, negative = 0;
            for (int k = 0; k < count; k++)
            {
                Vector3 a = v[hull.FaceVertices[start + k]];
                Vector3 b = v[hull.FaceVertices[start + (k + 1) % count]];
                float side = Vector3.Dot(Vector3.Cross(b - a, projected - a), n);
                if (side > 0f) positive++;
                else if (side < 0f) negative++;
            }
            if (positive == 0 || negative == 0) return projected;

            Vector3 point = projected + height * n;
            float best2 = float.MaxValue;
            Vector3 closest = projected;
            for (int k = 0; k < count; k++)
            {
                Vector3 a = v[hull.FaceVertices[start + k]];
                Vector3 b = v[hull.FaceVertices[start + (k + 1) % count]];
                Vector3 ab = b - a;
                float t = Math.Clamp(Vector3.Dot(point - a, ab) / MathF.Max(ab.LengthSquared(), 1e-20f), 0f, 1f);
                Vector3 q = a + t * ab;
                float d2 = (point - q).LengthSquared();
                if (d2 < best2) { best2 = d2; closest = q; }
            }
            return closest;
        }
    }
}
