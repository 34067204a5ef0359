#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>Unity face of <see cref="F.SphereCollider"/>.</summary>
    public sealed class FulcrumSphereCollider : FulcrumCollider
    {
        [Tooltip("Radius, metres (> 0).")] public float radius = 0.5f;

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.SphereCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c) => ((F.SphereCollider)c).radius = radius;

        /// <inheritdoc/>
        protected override void ClampFields() => radius = Mathf.Max(radius, Limits.MinShapeSize);
    }
}
