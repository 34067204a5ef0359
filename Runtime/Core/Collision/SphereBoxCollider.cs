using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Sphere (A) against box (B), in the box frame: outside, the closest point of the box is
    /// the centre clamped to the extents; inside, the sphere leaves through the nearest face.
    /// </summary>
    internal static class SphereBoxCollider
    {
        /// <summary>Pair function: A is a sphere, B a box.</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output)
        {
            float r = a.Radius;
            Vector3 h = b.HalfExtents;
            Vector3 c = poseB.InverseTransformPoint(poseA.Position);
            Vector3 q = Vector3.Clamp(c, -h, h);
            Vector3 nLocal;        // from the box towards the sphere centre
            float sep;
            if (q != c)
            {
                Vector3 d = c - q;
                float dist = d.Length();
                if (dist - r > output.Speculative) return;
                nLocal = d / dist;
                sep = dist - r;
            }
            else
            {
                // Inside: the face with the least depth.
                Vector3 depth = h - Vector3.Abs(c);
                int axis = depth.X <= depth.Y && depth.X <= depth.Z ? 0 : depth.Y <= depth.Z ? 1 : 2;
                float s = (axis == 0 ? c.X : axis == 1 ? c.Y : c.Z) >= 0 ? 1f : -1f;
                nLocal = axis == 0 ? new Vector3(s, 0, 0) : axis == 1 ? new Vector3(0, s, 0) : new Vector3(0, 0, s);
                float dd = axis == 0 ? depth.X : axis == 1 ? depth.Y : depth.Z;
                q = c + nLocal * dd;
                sep = -dd - r;
            }
            Vector3 n = poseB.TransformDirection(nLocal);
            Vector3 onBox = poseB.TransformPoint(q);
            Vector3 onSphere = poseA.Position - n * r;
            output.BeginPatch(-n);
            output.Add(0.5f * (onBox + onSphere), sep, 0);
        }
    }
}
