using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Queries on shapes at given poses, with no world: a ray against one shape, the closest
    /// point of a shape to a point, and the penetration of two shapes. The building blocks of
    /// the component layer's Collider.Raycast, ClosestPoint and ComputePenetration. Allocate
    /// nothing.
    /// </summary>
    public static class ShapeQueries
    {
        /// <summary>
        /// The first hit of the ray from <paramref name="origin"/> along
        /// <paramref name="direction"/> (any length, normalised here) with
        /// <paramref name="shape"/> at <paramref name="pose"/>, within
        /// <paramref name="maxDistance"/>. A ray that starts inside a solid shape does not hit it;
        /// meshes are hit from the front. Throws for a zero or non-finite direction.
        /// </summary>
        public static bool RayCast(in ShapeGeometry shape, in Pose pose, Vector3 origin, Vector3 direction, float maxDistance,
            out float distance, out Vector3 normal)
        {
            World.CheckQueryShape(shape, pose, false);
            Vector3 dir = World.CheckRay(origin, direction, ref maxDistance);
            return RayCaster.Cast(shape, pose, origin, dir, maxDistance, out distance, out normal);
        }

        /// <summary>
        /// The point of <paramref name="shape"/> at <paramref name="pose"/> closest to
        /// <paramref name="point"/>; the point itself when it is inside (as Unity's
        /// Physics.ClosestPoint). Spheres, capsules, boxes, hulls and planes; a triangle mesh
        /// throws (it has no inside).
        /// </summary>
        public static Vector3 ClosestPoint(in ShapeGeometry shape, in Pose pose, Vector3 point)
        {
            World.CheckQueryShape(shape, pose, false);
            if (!Validate.IsFinite(point)) throw new ArgumentException($"point must be finite, got {point}.", nameof(point));
            if (shape.Type == ShapeType.TriangleMesh)
                throw new ArgumentException("ClosestPoint needs a convex shape or a plane; a triangle mesh has no inside.", nameof(shape));
            if (shape.Type == ShapeType.Plane)
            {
                Vector3 n = pose.TransformDirection(shape.Normal);
                float above = Vector3.Dot(n, point) - (shape.Offset + Vector3.Dot(n, pose.Position));
                return above > 0 ? point - above * n : point;
            }
            SupportShape s = SupportShape.From(shape, pose);
            SupportShape p = SupportShape.Sphere(point, 0);
            float d = Gjk.Distance(s, p, out Vector3 onCore, out _, out _);
            if (d <= s.Radius) return point; // inside the core or within its radius
            return onCore + (point - onCore) * (s.Radius / d);
        }

        /// <summary>
        /// Whether the shapes overlap and, when they do, the shortest translation that separates
        /// them: move <paramref name="a"/> by <paramref name="direction"/> (unit) times
        /// <paramref name="distance"/> (metres, &gt; 0), as Unity's Physics.ComputePenetration.
        /// At least one shape must be convex; the other may be a plane (a triangle mesh throws:
        /// its penetration is one contact per triangle, which the world's narrow phase computes).
        /// </summary>
        public static bool Penetration(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB,
            out Vector3 direction, out float distance)
        {
            World.CheckQueryShape(a, poseA, false);
            World.CheckQueryShape(b, poseB, false);
            direction = default;
            distance = 0;
            if (a.Type == ShapeType.TriangleMesh || b.Type == ShapeType.TriangleMesh)
                throw new ArgumentException("Penetration works on convex shapes and planes; a triangle mesh is not supported.");
            if (a.Type == ShapeType.Plane && b.Type == ShapeType.Plane)
                throw new ArgumentException("Penetration needs at least one convex shape; both are planes.");
            if (b.Type == ShapeType.Plane) return PlanePenetration(a, poseA, b, poseB, 1f, out direction, out distance);
            if (a.Type == ShapeType.Plane) return PlanePenetration(b, poseB, a, poseA, -1f, out direction, out distance);

            SupportShape sa = SupportShape.From(a, poseA), sb = SupportShape.From(b, poseB);
            float radii = sa.Radius + sb.Radius;
            float gap = Gjk.Distance(sa, sb, out Vector3 pa, out Vector3 pb, out Simplex simplex);
            if (gap > CollisionMargins.CoreTolerance)
            {
                if (gap >= radii) return false;
                // Cores apart, radii overlapping: the cores' closest points give the axis.
                direction = (pa - pb) / gap;
                distance = radii - gap;
                return true;
            }
            // Cores overlap: EPA's normal points from A to B, so A moves the other way.
            if (Epa.Penetration(sa, sb, simplex, out Vector3 normal, out float depth, out _, out _))
            {
                direction = -normal;
                distance = depth + radii;
                return distance > 0;
            }
            // A flat difference (segments, points): fall back on the line between the centres.
            Vector3 c = sa.Center - sb.Center;
            float len = c.Length();
            direction = len > 1e-9f ? c / len : Vector3.UnitY;
            distance = radii;
            return radii > 0;
        }

        // The convex shape against a plane: the depth of its deepest point below the surface.
        // sign = +1 when the convex shape is the one to move, -1 when the plane is.
        static bool PlanePenetration(in ShapeGeometry convex, in Pose poseC, in ShapeGeometry plane, in Pose poseP, float sign,
            out Vector3 direction, out float distance)
        {
            Vector3 n = poseP.TransformDirection(plane.Normal);
            float offset = plane.Offset + Vector3.Dot(n, poseP.Position);
            SupportShape s = SupportShape.From(convex, poseC);
            Vector3 deepest = s.Support(-n, out _) - n * s.Radius;
            float depth = offset - Vector3.Dot(n, deepest);
            direction = sign * n;
            distance = depth > 0 ? depth : 0;
            return depth > 0;
        }
    }
}
