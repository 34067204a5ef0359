using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>Sphere (A) against capsule (B): a sphere against the closest point of the capsule's segment.</summary>
    internal static class SphereCapsuleCollider
    {
        /// <summary>Pair function: A is a sphere, B a capsule.</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output)
        {
            Vector3 axis = poseB.TransformDirection(new Vector3(0, b.HalfHeight, 0));
            Vector3 q = SegmentClosestPoints.OnSegment(poseB.Position - axis, poseB.Position + axis, poseA.Position, out _);
            SphereSphereCollider.Collide(poseA.Position, a.Radius, q, b.Radius, 0, output);
        }
    }
}
