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
        protected override F.Collider Create(F.Entity shadow)
        {
            var c = shadow.AddComponent<F.CapsuleCollider>();
            c.radius = radius;
            c.height = height;
            c.direction = direction;
            return c;
        }
    }
}
