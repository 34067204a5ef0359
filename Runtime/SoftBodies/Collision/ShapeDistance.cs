using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The signed distance from a point to a rigid shape and the outward normal at the closest
    /// surface point, one function per shape kind (convex hulls in <see cref="HullDistance"/>).
    /// Triangle meshes are not answered here: a vertex meets a mesh one triangle at a time
    /// through the mesh's BVH (<see cref="MeshVertexContacts"/>), so they report no contact.
    /// </summary>
    internal static class ShapeDistance
    {
        /// <summary>
        /// True when <paramref name="point"/> (world) is closer than <paramref name="radius"/> to
        /// the shape's surface or inside it; then <paramref name="distance"/> is the signed
        /// distance (negative inside) and <paramref name="normal"/> the world outward normal.
        /// </summary>
        public static bool Query(in ShapeGeometry shape, in Pose pose, Vector3 point, float radius, out float distance, out Vector3 normal)
        {
            Vector3 local = pose.InverseTransformPoint(point);
            bool hit;
            Vector3 localNormal;
            switch (shape.Type)
            {
                case ShapeType.Sphere: hit = Sphere(shape.Radius, local, radius, out distance, out localNormal); break;
                case ShapeType.Box: hit = Box(shape.HalfExtents, local, radius, out distance, out localNormal); break;
                case ShapeType.Capsule: hit = Capsule(shape.Radius, shape.HalfHeight, local, radius, out distance, out localNormal); break;
                case ShapeType.Plane: hit = Plane(shape.Normal, shape.Offset, local, radius, out distance, out localNormal); break;
                case ShapeType.ConvexHull: hit = HullDistance.Query((ConvexHull)shape.Data!, local, radius, out distance, out localNormal); break;
                default:
                    distance = float.MaxValue;
                    normal = Vector3.Zero;
                    return false;
            }
            normal = hit ? pose.TransformDirection(localNormal) : Vector3.Zero;
            return hit;
        }

        public static bool Sphere(float sphereRadius, Vector3 p, float radius, out float distance, out Vector3 normal)
        {
            float d2 = p.LengthSquared();
            float reach = sphereRadius + radius;
            if (d2 >= reach * reach)
            {
                distance = float.MaxValue;
                normal = Vector3.Zero;
                return false;
            }
            float d = MathF.Sqrt(d2);
            normal = d > 1e-9f ? p / d : Vector3.UnitY;
            distance = d - sphereRadius;
            return true;
        }

        public static bool Capsule(float capsuleRadius, float halfHeight, Vector3 p, float radius, out float distance, out Vector3 normal)
        {
            Vector3 axis = new Vector3(0, Math.Clamp(p.Y, -halfHeight, halfHeight), 0);
            return Sphere(capsuleRadius, p - axis, radius, out distance, out normal);
        }

        public static bool Plane(Vector3 planeNormal, float offset, Vector3 p, float radius, out float distance, out Vector3 normal)
        {
            distance = Vector3.Dot(planeNormal, p) - offset;
            normal = planeNormal;
            return distance < radius;
        }

        public static bool Box(Vector3 half, Vector3 p, float radius, out float distance, out Vector3 normal)
        {
            Vector3 q = Vector3.Abs(p) - half;
            if (q.X > radius || q.Y > radius || q.Z > radius)
            {
                distance = float.MaxValue;
                normal = Vector3.Zero;
                return false;
            }
            if (q.X > 0 || q.Y > 0 || q.Z > 0)
            {
                // Outside: the closest point is the clamp onto the box.
                Vector3 outside = Vector3.Max(q, Vector3.Zero);
                float d = outside.Length();
                if (d >= radius)
                {
                    distance = d;
                    normal = Vector3.Zero;
                    return false;
                }
                Vector3 signs = new Vector3(p.X < 0 ? -1 : 1, p.Y < 0 ? -1 : 1, p.Z < 0 ? -1 : 1);
                normal = outside * signs / d;
                distance = d;
                return true;
            }
            // Inside: out through the nearest face.
            if (q.X >= q.Y && q.X >= q.Z)
            {
                distance = q.X;
                normal = new Vector3(p.X < 0 ? -1 : 1, 0, 0);
            }
            else if (q.Y >= q.Z)
            {
                distance = q.Y;
                normal = new Vector3(0, p.Y < 0 ? -1 : 1, 0);
            }
            else
            {
                distance = q.Z;
                normal = new Vector3(0, 0, p.Z < 0 ? -1 : 1);
            }
            return true;
        }
    }
}
