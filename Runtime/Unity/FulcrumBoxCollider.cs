#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>Unity face of <see cref="F.BoxCollider"/>.</summary>
    public sealed class FulcrumBoxCollider : FulcrumCollider
    {
        [SerializeField, Tooltip("Full size, metres (each > 0).")] Vector3 m_Size = Vector3.one;

        /// <summary>Full size, metres (each &gt; 0).</summary>
        public Vector3 size { get => m_Size; set { m_Size = value; Push(); } }

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.BoxCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c) => ((F.BoxCollider)c).size = m_Size.ToNumerics();

        /// <inheritdoc/>
        protected override void ClampFields() =>
            m_Size = new Vector3(Mathf.Max(m_Size.x, Limits.MinShapeSize), Mathf.Max(m_Size.y, Limits.MinShapeSize), Mathf.Max(m_Size.z, Limits.MinShapeSize));
    }
}
