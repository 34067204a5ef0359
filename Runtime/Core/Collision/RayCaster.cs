using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A ray (origin, unit direction, length) against one shape, in the shape's frame. Rays
    /// that start inside a solid shape do not hit it (as in Unity); meshes are hit from their
    /// front side only.
    /// </summary>
    internal static class RayCaster
    {
        /// <summary>The first hit of the ray with the shape at its pose: distance and world normal.</summary>
        public static bool Cast(in ShapeGeometry g, in Pose pose, Vector3 origin, Vector3 direction, float maxDistance, out float distance, out Vector3 normal)
        {
            Vector3 o = pose.InverseTransformPoint(origin);
            Vector3 d = pose.InverseTransformDirection(direction);
            bool hit;
            Vector3 n;
            switch (g.Type)
            {
                case ShapeType.Sphere: hit = Sphere(o, d, Vector3.Zero, g.Radius, maxDistance, out distance, out n); break;
                case ShapeType.Box: hit = Box(o, d, g.HalfExtents, maxDistance, out distance, out n); break;
                case ShapeType.Capsule: hit = Capsule(o, d, g.Radius, g.HalfHeight, maxDistance, out distance, out n); break;
                case ShapeType.Plane: hit = Plane(o, d, g.Normal, g.Offset, maxDistance, out distance, out n); break;
                case ShapeType.ConvexHull: hit = Hull((ConvexHull)g.Data!, o, d, maxDistance, out distance, out n); break;
                case ShapeType.TriangleMesh: hit = Mesh((TriangleMesh)g.Data!, o, d, maxDistance, out distance, out n); break;
                default: distance = 0; n = default; hit = false; break;
            }
            normal = hit ? pose.TransformDirection(n) : default;
            return hit;
        }

        public static bool Sphere(Vector3 o, Vector3 d, Vector3 center, float r, float max, out float t, out Vector3 n)
        {
            t = 0;
            n = default;
            Vector3 m = o - center;
            float b = Vector3.Dot(m, d), c = m.LengthSquared() - r * r;
            if (c <= 0 || b > 0) return false;
            float disc = b * b - c;
            if (disc < 0) return false;
            t = MathF.Max(0, -b - MathF.Sqrt(disc));
            if (t > max) return false;
            n = Vector3.Normalize(m + t * d);
            return true;
        }

        static bool Box(Vector3 o, Vector3 d, Vector3 h, float max, out float t, out Vector3 n)
        {
            t = 0;
            n = default;
            float enter = float.MinValue, exit = max;
            int axis = -1;
            float sign = 0;
            for (int k = 0; k < 3; k++)
            {
                if (!Slab.Cross(o, d, h, k, 1e-12f, out float t1, out float t2, out bool atPlus)) return false;
                if (t1 > enter) { enter = t1; axis = k; sign = atPlus ? 1 : -1; }
                exit = MathF.Min(exit, t2);
            }
            if (axis < 0 || enter < 0 || enter > exit) return false;
            t = enter;
            n = axis == 0 ? new Vector3(sign, 0, 0) : axis == 1 ? new Vector3(0, sign, 0) : new Vector3(0, 0, sign);
            return true;
        }

        static bool Capsule(Vector3 o, Vector3 d, float r, float h, float max, out float t, out Vector3 n)
        {
            t = 0;
            n = default;
            // Inside: no hit.
            Vector3 q = new Vector3(0, Math.Clamp(o.Y, -h, h), 0);
            if ((o - q).LengthSquared() <= r * r) return false;
            float best = float.MaxValue;
            // The side: x^2 + z^2 = r^2 with |y| <= h.
            float a = d.X * d.X + d.Z * d.Z, b = o.X * d.X + o.Z * d.Z, c = o.X * o.X + o.Z * o.Z - r * r;
            if (a > 1e-12f)
            {
                float disc = b * b - a * c;
                if (disc >= 0)
                {
                    float ts = (-b - MathF.Sqrt(disc)) / a;
                    float y = o.Y + ts * d.Y;
                    if (ts >= 0 && ts <= max && MathF.Abs(y) <= h)
                    {
                        best = ts;
                        n = Vector3.Normalize(new Vector3(o.X + ts * d.X, 0, o.Z + ts * d.Z));
                    }
                }
            }
            for (int end = -1; end <= 1; end += 2)
                if (Sphere(o, d, new Vector3(0, end * h, 0), r, max, out float te, out Vector3 ne) && te < best)
                {
                    best = te;
                    n = ne;
                }
            if (best == float.MaxValue) return false;
            t = best;
            return true;
        }

        static bool Plane(Vector3 o, Vector3 d, Vector3 normal, float offset, float max, out float t, out Vector3 n)
        {
            t = 0;
            n = normal;
            float gap = Vector3.Dot(normal, o) - offset, rate = Vector3.Dot(normal, d);
            if (gap <= 0 || rate >= 0) return false;
            t = -gap / rate;
            return t <= max;
        }

        // Cyrus-Beck clipping of the ray by the face planes.
        static bool Hull(ConvexHull hull, Vector3 o, Vector3 d, float max, out float t, out Vector3 n)
        {
            t = 0;
            n = default;
            float enter = float.MinValue, exit = max;
            int face = -1;
            for (int f = 0; f < hull.FaceCount; f++)
            {
                Vector3 fn = hull.FaceNormals[f];
                float num = hull.FaceOffsets[f] - Vector3.Dot(fn, o), den = Vector3.Dot(fn, d);
                if (MathF.Abs(den) < 1e-12f)
                {
                    if (num < 0) return false;
                    continue;
                }
                float tf = num / den;
                if (den < 0) { if (tf > enter) { enter = tf; face = f; } }
                else exit = MathF.Min(exit, tf);
                if (enter > exit) return false;
            }
            if (face < 0 || enter < 0) return false;
            t = enter;
            n = hull.FaceNormals[face];
            return true;
        }

        struct TriangleRay : ITreeRayCallback
        {
            public TriangleMesh Mesh;
            public Vector3 Origin, Direction;
            public float Length;
            public int Hit;

            public float Visit(int proxyId, int triangle, float maxFraction)
            {
                if (Triangle(Mesh, triangle, Origin, Direction, maxFraction * Length, out float t))
                {
                    Hit = triangle;
                    return t / Length;
                }
                return maxFraction;
            }
        }

        static bool Mesh(TriangleMesh mesh, Vector3 o, Vector3 d, float max, out float t, out Vector3 n)
        {
            var ray = new TriangleRay { Mesh = mesh, Origin = o, Direction = d, Length = MathF.Max(max, 1e-12f), Hit = -1 };
            // The BVH walks the segment o + s (d max), s in [0, 1].
            mesh.Bvh.RayCast(o, d * ray.Length, 1f, ref ray);
            t = 0;
            n = default;
            if (ray.Hit < 0) return false;
            Triangle(mesh, ray.Hit, o, d, max, out t);
            n = mesh.Normals[ray.Hit];
            return true;
        }

        // Moller and Trumbore (1997), front faces only.
        internal static bool Triangle(TriangleMesh mesh, int tri, Vector3 o, Vector3 d, float max, out float t)
        {
            t = 0;
            if (Vector3.Dot(mesh.Normals[tri], d) >= 0) return false;
            mesh.GetTriangle(tri, out Vector3 a, out Vector3 b, out Vector3 c);
            Vector3 e1 = b - a, e2 = c - a, p = Vector3.Cross(d, e2);
            float det = Vector3.Dot(e1, p);
            if (MathF.Abs(det) < 1e-20f) return false;
            float inv = 1 / det;
            Vector3 s = o - a;
            float u = Vector3.Dot(s, p) * inv;
            if (u < 0 || u > 1) return false;
            Vector3 q = Vector3.Cross(s, e1);
            float v = Vector3.Dot(d, q) * inv;
            if (v < 0 || u + v > 1) return false;
            t = Vector3.Dot(e2, q) * inv;
            return t >= 0 && t <= max;
        }
    }
}
