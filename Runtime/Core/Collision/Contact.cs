using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A persistent pair of shapes whose fat bounds overlap, from the step the broad phase
    /// finds it until the bounds part or a shape goes. Shape A has the lower
    /// <see cref="ShapeType"/> (the pair-function table's order); its manifolds (one for a
    /// convex pair, up to <see cref="ContactGraph.MaxManifoldsPerPair"/> against a mesh) are a
    /// chain in <see cref="ContactGraph.Manifolds"/> that keeps last step's impulses.
    /// </summary>
    internal struct Contact
    {
        public int ShapeA;
        public int ShapeB;
        public int BodyA;
        public int BodyB;
        public ulong Key;               // PairMap.Key(ShapeA, ShapeB)
        public int FirstManifold;       // -1 when none
        public int ManifoldCount;
        public int DenseIndex;          // position in ContactGraph.Dense, -1 when free
        public ContactFlags Flags;
        public Vector3 RelativeVelocity; // at the manifold's mean point, before the solve
        // Manifold reuse (ContactFlags.Reusable): B's pose in A's frame and the speculative
        // distance when the manifolds were last computed by the pair function.
        public Vector3 ReusePosition;
        public Quaternion ReuseRotation;
        public float ReuseSpeculative;
    }
}
