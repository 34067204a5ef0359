#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>Unity face of <see cref="F.CapsuleCollider"/>.</summary>
    public sealed class FulcrumCapsuleCollider : FulcrumCollider
    {
        [Tooltip("Radius, metres (> 0).")] public float radius = 0.5f;
        [Tooltip("Full height including the caps, metres.")] public float height = 2f;
        [Tooltip("Axis: 0 = x, 1 = y, 2 = z.")] public int direction = 1;

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.CapsuleCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c)
        {
            var capsule = (F.CapsuleCollider)c;
            capsule.radius = radius;
            capsule.height = height;
            capsule.direction = direction;
        }

        /// <inheritdoc/>
        protected override void ClampFields()
        {
            radius = Mathf.Max(radius, Limits.MinShapeSize);
            height = Mathf.Max(height, Limits.MinShapeSize);
            direction = Mathf.Clamp(direction, 0, 2);
        }
    }
}
