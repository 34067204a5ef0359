using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// BVH callback of continuous collision against a mesh: the time of impact of the
    /// sweeping shape with each triangle it starts in front of (triangles are one-sided).
    /// </summary>
    internal struct CcdTriangles : ITreeOverlapCallback
    {
        public TriangleMesh Mesh;
        public Pose MeshPose;
        public ShapeGeometry Geometry;
        public Pose LocalPose;
        public BodySweep Sweep;
        public float Bound;
        public float TargetGap;
        public float Tolerance;
        public float FastApproach;
        public float Toi;

        public bool Visit(int proxyId, int triangle)
        {
            Mesh.GetTriangle(triangle, MeshPose, out Vector3 a, out Vector3 b, out Vector3 c);
            Vector3 n = MeshPose.TransformDirection(Mesh.Normals[triangle]);
            // Starting behind the triangle: the back side never collides.
            Vector3 start = (Sweep.BodyPose(0) * LocalPose).Position;
            if (Vector3.Dot(n, start - a) < 0) return true;
            if (TimeOfImpact.Compute(Geometry, LocalPose, Sweep, Bound, SupportShape.Triangle(a, b, c), false, default, 0,
                    TargetGap, Tolerance, FastApproach, Toi, out float toi) && toi < Toi)
                Toi = toi;
            return Toi > 0;
        }
    }
}
