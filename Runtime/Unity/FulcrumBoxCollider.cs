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
        protected override F.Collider Create(F.Entity shadow)
        {
            var c = shadow.AddComponent<F.BoxCollider>();
            c.size = size.ToNumerics();
            return c;
        }
    }
}
