#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>Unity face of <see cref="F.SphereCollider"/>.</summary>
    public sealed class FulcrumSphereCollider : FulcrumCollider
    {
        [SerializeField, Tooltip("Radius, metres (> 0).")] float m_Radius = 0.5f;

        /// <summary>Radius, metres (&gt; 0).</summary>
        public float radius { get => m_Radius; set { m_Radius = value; Push(); } }

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.SphereCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c) => ((F.SphereCollider)c).radius = m_Radius;

        /// <inheritdoc/>
        protected override void ClampFields() => m_Radius = Mathf.Max(m_Radius, Limits.MinShapeSize);
    }
}
