using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Convex shapes (A) against a half-space (B): every core vertex of A (sphere centre,
    /// capsule ends, box corners, hull vertices) closer to the plane than the speculative
    /// distance plus its radius becomes a point with the vertex index as feature id; the
    /// manifold reduction keeps the best four. The normal from A to B is minus the plane
    /// normal.
    /// </summary>
    internal static class PlaneCollider
    {
        /// <summary>Pair function: A is a sphere, box, capsule or hull; B a plane.</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output)
        {
            Vector3 n = poseB.TransformDirection(b.Normal);
            float offset = Vector3.Dot(n, poseB.TransformPoint(b.Normal * b.Offset));
            output.BeginPatch(-n);
            switch (a.Type)
            {
                case ShapeType.Sphere:
                    AddVertex(poseA.Position, a.Radius, 0, n, offset, output);
                    break;
                case ShapeType.Capsule:
                {
                    Vector3 axis = poseA.TransformDirection(new Vector3(0, a.HalfHeight, 0));
                    AddVertex(poseA.Position - axis, a.Radius, 0, n, offset, output);
                    AddVertex(poseA.Position + axis, a.Radius, 1, n, offset, output);
                    break;
                }
                case ShapeType.Box:
                {
                    Mat3 r = Mat3.FromQuaternion(poseA.Rotation);
                    Vector3 h = a.HalfExtents;
                    Vector3 x = r.C0 * h.X, y = r.C1 * h.Y, z = r.C2 * h.Z;
                    for (uint i = 0; i < 8; i++)
                    {
                        Vector3 v = poseA.Position + ((i & 1) != 0 ? x : -x) + ((i & 2) != 0 ? y : -y) + ((i & 4) != 0 ? z : -z);
                        AddVertex(v, 0, i, n, offset, output);
                    }
                    break;
                }
                case ShapeType.ConvexHull:
                {
                    var hull = (ConvexHull)a.Data!;
                    Mat3 r = Mat3.FromQuaternion(poseA.Rotation);
                    Vector3[] vs = hull.Vertices;
                    for (int i = 0; i < vs.Length; i++)
                        AddVertex(poseA.Position + r * vs[i], 0, (uint)i, n, offset, output);
                    break;
                }
            }
        }

        static void AddVertex(Vector3 core, float radius, uint id, Vector3 n, float offset, ContactBuffer output)
        {
            float sep = Vector3.Dot(n, core) - offset - radius;
            Vector3 surface = core - n * radius;
            output.Add(surface - n * (0.5f * sep), sep, id);
        }
    }
}
