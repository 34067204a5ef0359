#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>What a Fulcrum query hit, in Unity's types (Unity's RaycastHit).</summary>
    public struct FulcrumRaycastHit
    {
        /// <summary>The hit point, world.</summary>
        public Vector3 point;
        /// <summary>The surface normal there.</summary>
        public Vector3 normal;
        /// <summary>How far the ray (or the cast shape's centre) travelled, metres.</summary>
        public float distance;
        /// <summary>The Unity collider hit (null if it has no Unity face, e.g. made from code on the headless scene).</summary>
        public FulcrumCollider? collider;
        /// <summary>The headless collider hit.</summary>
        public F.Collider? fulcrumCollider;

        /// <summary>The collider's rigidbody, or null for a static collider.</summary>
        public readonly FulcrumRigidbody? rigidbody => collider != null ? collider.attachedRigidbody : null;

        /// <summary>The collider's transform.</summary>
        public readonly Transform? transform => collider != null ? collider.transform : null;

        /// <summary>A headless hit with its collider's Unity face.</summary>
        public static FulcrumRaycastHit From(in F.RaycastHit hit)
        {
            FulcrumWorld? w = FulcrumWorld.Current;
            return new FulcrumRaycastHit
            {
                point = hit.point.ToUnity(),
                normal = hit.normal.ToUnity(),
                distance = hit.distance,
                fulcrumCollider = hit.collider,
                collider = w != null ? w.FaceOf(hit.collider) : null,
            };
        }
    }
}
