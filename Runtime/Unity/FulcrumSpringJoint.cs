#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// A spring between the anchors with optional distance limits (Unity's SpringJoint), on
    /// <see cref="F.DistanceJoint"/>. <see cref="spring"/> (N/m) and <see cref="damper"/> (N s/m)
    /// are Unity's units, turned into Fulcrum's stable frequency and damping ratio with the two
    /// bodies' reduced mass m = mA mB / (mA + mB) when the joint is enabled: f = √(k/m) / 2π,
    /// ζ = c / (2√(km)). The spring's rest length is the distance at enable time (Unity's too).
    /// </summary>
    public sealed class FulcrumSpringJoint : FulcrumJoint
    {
        [SerializeField, Tooltip("Stiffness, N/m.")] float m_Spring = 10f;
        [SerializeField, Tooltip("Damping, N s/m.")] float m_Damper = 0.2f;
        [SerializeField, Tooltip("Shortest distance, m (0 = none).")] float m_MinDistance;
        [SerializeField, Tooltip("Longest distance, m (0 = none).")] float m_MaxDistance;

        /// <summary>Stiffness, N/m.</summary>
        public float spring { get => m_Spring; set { m_Spring = value; Push(); } }
        /// <summary>Damping, N s/m.</summary>
        public float damper { get => m_Damper; set { m_Damper = value; Push(); } }
        /// <summary>Shortest distance, m (0 = none).</summary>
        public float minDistance { get => m_MinDistance; set { m_MinDistance = value; Push(); } }
        /// <summary>Longest distance, m (0 = none).</summary>
        public float maxDistance { get => m_MaxDistance; set { m_MaxDistance = value; Push(); } }

        /// <inheritdoc/>
        protected override F.Joint Create(F.Entity shadow) => shadow.AddComponent<F.DistanceJoint>();

        /// <inheritdoc/>
        protected override void PushKind(F.Joint j)
        {
            var d = (F.DistanceJoint)j;
            float own = GetComponent<FulcrumRigidbody>().mass;
            FulcrumRigidbody? other = connectedBody;
            float reduced = other != null && !other.isKinematic ? own * other.mass / (own + other.mass) : own;
            float k = Mathf.Max(m_Spring, 0f), c = Mathf.Max(m_Damper, 0f);
            // Each headless setter rebuilds the joint (a new rest length): assign only what changed.
            float hz = k > 0 ? Mathf.Sqrt(k / reduced) / (2f * Mathf.PI) : 0f;
            float ratio = k > 0 ? c / (2f * Mathf.Sqrt(k * reduced)) : 0f;
            float min = m_MinDistance > 0 ? m_MinDistance : 0f;
            float max = m_MaxDistance > 0 ? m_MaxDistance : float.PositiveInfinity;
            if (d.spring != hz) d.spring = hz;
            if (d.damper != ratio) d.damper = ratio;
            if (d.minDistance != min) d.minDistance = min;
            if (d.maxDistance != max) d.maxDistance = max;
        }
    }
}
