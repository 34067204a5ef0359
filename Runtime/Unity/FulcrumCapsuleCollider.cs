#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>Unity face of <see cref="F.CapsuleCollider"/>.</summary>
    public sealed class FulcrumCapsuleCollider : FulcrumCollider
    {
        [SerializeField, Tooltip("Radius, metres (> 0).")] float m_Radius = 0.5f;
        [SerializeField, Tooltip("Full height including the caps, metres.")] float m_Height = 2f;
        [SerializeField, Tooltip("Axis: 0 = x, 1 = y, 2 = z.")] int m_Direction = 1;

        /// <summary>Radius, metres (&gt; 0).</summary>
        public float radius { get => m_Radius; set { m_Radius = value; Push(); } }

        /// <summary>Full height including the caps, metres.</summary>
        public float height { get => m_Height; set { m_Height = value; Push(); } }

        /// <summary>Axis: 0 = x, 1 = y, 2 = z.</summary>
        public int direction { get => m_Direction; set { m_Direction = value; Push(); } }

        /// <inheritdoc/>
        protected override F.Collider Create(F.Entity shadow) => shadow.AddComponent<F.CapsuleCollider>();

        /// <inheritdoc/>
        protected override void PushShape(F.Collider c)
        {
            var capsule = (F.CapsuleCollider)c;
            capsule.radius = m_Radius;
            capsule.height = m_Height;
            capsule.direction = m_Direction;
        }

        /// <inheritdoc/>
        protected override void ClampFields()
        {
            m_Radius = Mathf.Max(m_Radius, Limits.MinShapeSize);
            m_Height = Mathf.Max(m_Height, Limits.MinShapeSize);
            m_Direction = Mathf.Clamp(m_Direction, 0, 2);
        }
    }
}
