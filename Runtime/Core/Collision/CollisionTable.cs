using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The pair function for each (shape type, shape type), filled once. A pair registered
    /// one way round is also reachable the other way: the function runs with A and B swapped
    /// and the normals are turned around. Pairs of two static-only kinds (plane, mesh) have
    /// no function: they never meet.
    /// </summary>
    internal static class CollisionTable
    {
        const int Kinds = 6;
        static readonly PairFunction?[] Functions = new PairFunction?[Kinds * Kinds];
        static readonly bool[] Swapped = new bool[Kinds * Kinds];

        static CollisionTable()
        {
            Register(ShapeType.Sphere, ShapeType.Sphere, SphereSphereCollider.Collide);
            Register(ShapeType.Sphere, ShapeType.Box, SphereBoxCollider.Collide);
            Register(ShapeType.Sphere, ShapeType.Capsule, SphereCapsuleCollider.Collide);
            Register(ShapeType.Capsule, ShapeType.Capsule, CapsuleCapsuleCollider.Collide);
            Register(ShapeType.Capsule, ShapeType.Box, CapsuleBoxCollider.Collide);
            Register(ShapeType.Box, ShapeType.Box, BoxBoxCollider.Collide);
            Register(ShapeType.Sphere, ShapeType.Plane, PlaneCollider.Collide);
            Register(ShapeType.Box, ShapeType.Plane, PlaneCollider.Collide);
            Register(ShapeType.Capsule, ShapeType.Plane, PlaneCollider.Collide);
            Register(ShapeType.ConvexHull, ShapeType.Plane, PlaneCollider.Collide);
            Register(ShapeType.Sphere, ShapeType.ConvexHull, ConvexCollider.Collide);
            Register(ShapeType.Box, ShapeType.ConvexHull, ConvexCollider.Collide);
            Register(ShapeType.Capsule, ShapeType.ConvexHull, ConvexCollider.Collide);
            Register(ShapeType.ConvexHull, ShapeType.ConvexHull, ConvexCollider.Collide);
            Register(ShapeType.Sphere, ShapeType.TriangleMesh, MeshCollider.Collide);
            Register(ShapeType.Box, ShapeType.TriangleMesh, MeshCollider.Collide);
            Register(ShapeType.Capsule, ShapeType.TriangleMesh, MeshCollider.Collide);
            Register(ShapeType.ConvexHull, ShapeType.TriangleMesh, MeshCollider.Collide);
        }

        static void Register(ShapeType a, ShapeType b, PairFunction f)
        {
            int ab = (int)a * Kinds + (int)b, ba = (int)b * Kinds + (int)a;
            Functions[ab] = f;
            Swapped[ab] = false;
            if (ab == ba) return;
            Functions[ba] = f;
            Swapped[ba] = true;
        }

        /// <summary>True when shapes of these types can collide.</summary>
        public static bool Has(ShapeType a, ShapeType b) => Functions[(int)a * Kinds + (int)b] != null;

        /// <summary>Runs the pair function of the two shapes' types (nothing when there is none).</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output)
        {
            int k = (int)a.Type * Kinds + (int)b.Type;
            PairFunction? f = Functions[k];
            if (f == null) return;
            if (Swapped[k])
            {
                f(b, poseB, a, poseA, output);
                output.FlipNormals();
            }
            else f(a, poseA, b, poseB, output);
        }
    }
}
