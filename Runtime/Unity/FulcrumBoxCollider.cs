#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>Unity face of <see cref="F.BoxCollider"/>.</summary>
    public sealed class FulcrumBoxCollider : FulcrumCollider
    {
        [Tooltip("Full size, metres (each > 0).")] public Vector3 size = Vector3.one;

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.BoxCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c) => ((F.BoxCollider)c).size = size.ToNumerics();

        /// <inheritdoc/>
        protected override void ClampFields() =>
            size = new Vector3(Mathf.Max(size.x, Limits.MinShapeSize), Mathf.Max(size.y, Limits.MinShapeSize), Mathf.Max(size.z, Limits.MinShapeSize));
    }
}
