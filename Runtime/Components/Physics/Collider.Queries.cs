using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    public abstract partial class Collider
    {
        PhysicsMaterial? _instanceMaterial;

        /// <summary>
        /// This collider's own material (Unity's Collider.material): the first read makes a copy
        /// of <see cref="sharedMaterial"/> (or of the defaults) used by this collider alone, so
        /// editing it changes no other collider. Setting it assigns the material as
        /// <see cref="sharedMaterial"/> does.
        /// </summary>
        public PhysicsMaterial material
        {
            get
            {
                ThrowIfDestroyed();
                if (_instanceMaterial != null && sharedMaterial == _instanceMaterial) return _instanceMaterial;
                PhysicsMaterial? from = sharedMaterial;
                var copy = new PhysicsMaterial((from?.name ?? "Default") + " (Instance)");
                if (from != null)
                {
                    copy.dynamicFriction = from.dynamicFriction;
                    copy.staticFriction = from.staticFriction;
                    copy.bounciness = from.bounciness;
                    copy.frictionCombine = from.frictionCombine;
                    copy.bounceCombine = from.bounceCombine;
                }
                _instanceMaterial = copy;
                sharedMaterial = copy;
                return copy;
            }
            set
            {
                sharedMaterial = value;
                _instanceMaterial = value;
            }
        }

        /// <summary>
        /// The ray's first hit with this collider alone, where it is now, within
        /// <paramref name="maxDistance"/> (Unity's Collider.Raycast). False without a shape (disabled
        /// or inactive). A ray starting inside does not hit; meshes are hit from the front.
        /// </summary>
        public bool Raycast(Ray ray, out RaycastHit hitInfo, float maxDistance)
        {
            ThrowIfDestroyed();
            hitInfo = default;
            if (!HasShape) return false;
            Pose pose = ShapePose();
            if (!ShapeQueries.RayCast(scene.world.GetShapeGeometry(_shape), pose, ray.origin, ray.direction, maxDistance, out float d, out Vector3 n))
                return false;
            hitInfo = new RaycastHit { point = ray.GetPoint(d), normal = n, distance = d, collider = this };
            return true;
        }

        /// <summary>
        /// The point of this collider closest to <paramref name="position"/>, where the collider
        /// is now; the position itself when inside (Unity's Collider.ClosestPoint). Without a
        /// shape, the position. A non-convex MeshCollider throws.
        /// </summary>
        public Vector3 ClosestPoint(Vector3 position)
        {
            ThrowIfDestroyed();
            FieldCheck.Finite(position, this, nameof(position));
            if (!HasShape) return position;
            return ShapeQueries.ClosestPoint(scene.world.GetShapeGeometry(_shape), ShapePose(), position);
        }

        /// <summary>The point of <see cref="bounds"/> closest to <paramref name="position"/> (Unity's ClosestPointOnBounds).</summary>
        public Vector3 ClosestPointOnBounds(Vector3 position)
        {
            ThrowIfDestroyed();
            FieldCheck.Finite(position, this, nameof(position));
            Aabb b = bounds;
            return b.IsValid ? Vector3.Clamp(position, b.Min, b.Max) : position;
        }

        // The shape's world pose now: its body's pose times its local pose.
        Pose ShapePose()
        {
            World w = scene.world;
            return w.GetBody(w.GetShapeBody(_shape)).Pose * w.GetShapeLocalPose(_shape);
        }
    }
}
