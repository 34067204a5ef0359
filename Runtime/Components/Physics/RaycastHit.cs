using System.Numerics;

namespace Fulcrum.Components
{
    /// <summary>What a ray or sphere cast hit (Unity's RaycastHit).</summary>
    public struct RaycastHit
    {
        /// <summary>The hit point on the collider's surface, world, metres.</summary>
        public Vector3 point;
        /// <summary>The surface normal there (unit, facing the query).</summary>
        public Vector3 normal;
        /// <summary>Distance travelled by the ray (or the sphere's centre) to the hit, metres.</summary>
        public float distance;
        /// <summary>The collider hit.</summary>
        public Collider collider;
        /// <summary>The collider's rigidbody, or null for a static collider.</summary>
        public readonly Rigidbody? rigidbody => collider?.attachedRigidbody;
        /// <summary>The collider's entity.</summary>
        public readonly Entity? entity => collider?.entity;
        /// <summary>The collider's transform.</summary>
        public readonly Transform? transform => collider?.transform;
    }
}
