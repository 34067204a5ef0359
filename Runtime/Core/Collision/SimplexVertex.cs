using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>A vertex of a GJK simplex: support points on both cores and their difference.</summary>
    internal struct SimplexVertex
    {
        public Vector3 A;       // support point on core A
        public Vector3 B;       // support point on core B
        public Vector3 W;       // A - B, a point of the Minkowski difference
        public int IndexA;
        public int IndexB;
        public float Weight;    // barycentric weight of the closest point

        public SimplexVertex(Vector3 a, int indexA, Vector3 b, int indexB)
        {
            A = a;
            B = b;
            W = a - b;
            IndexA = indexA;
            IndexB = indexB;
            Weight = 1;
        }
    }
}
