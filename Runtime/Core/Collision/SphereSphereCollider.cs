using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Sphere against sphere: one point on the line of centres. Coincident centres take the
    /// world up axis as normal (any unit vector is a valid answer; a fixed one is
    /// deterministic).
    /// </summary>
    internal static class SphereSphereCollider
    {
        /// <summary>Pair function: A and B are spheres.</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output) =>
            Collide(poseA.Position, a.Radius, poseB.Position, b.Radius, 0, output);

        /// <summary>Two spheres given by centre and radius; <paramref name="id"/> is the feature id.</summary>
        public static void Collide(Vector3 centerA, float radiusA, Vector3 centerB, float radiusB, uint id, ContactBuffer output)
        {
            Vector3 d = centerB - centerA;
            float dist2 = d.LengthSquared();
            float reach = radiusA + radiusB + output.Speculative;
            if (dist2 > reach * reach) return;
            float dist = MathF.Sqrt(dist2);
            Vector3 n = dist > CollisionMargins.CoreTolerance ? d / dist : Vector3.UnitY;
            float sep = dist - radiusA - radiusB;
            Vector3 pa = centerA + n * radiusA, pb = centerB - n * radiusB;
            output.BeginPatch(n);
            output.Add(0.5f * (pa + pb), sep, id);
        }
    }
}
