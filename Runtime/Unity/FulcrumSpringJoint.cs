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
        [Tooltip("Stiffness, N/m.")] public float spring = 10f;
        [Tooltip("Damping, N s/m.")] public float damper = 0.2f;
        [Tooltip("Shortest distance, m (0 = none).")] public float minDistance;
        [Tooltip("Longest distance, m (0 = none).")] public float maxDistance;

        /// <inheritdoc/>
        protected override F.Joint Create(F.Entity shadow) => shadow.AddComponent<F.DistanceJoint>();

        /// <inheritdoc/>
        protected override void PushKind(F.Joint j)
        {
            var d = (F.DistanceJoint)j;
            float own = GetComponent<FulcrumRigidbody>().mass;
            float reduced = connectedBody != null && !connectedBody.isKinematic ? own * connectedBody.mass / (own + connectedBody.mass) : own;
            float k = Mathf.Max(spring, 0f), c = Mathf.Max(damper, 0f);
            d.spring = k > 0 ? Mathf.Sqrt(k / reduced) / (2f * Mathf.PI) : 0f;
            d.damper = k > 0 ? c / (2f * Mathf.Sqrt(k * reduced)) : 0f;
            d.minDistance = minDistance > 0 ? minDistance : 0f;
            d.maxDistance = maxDistance > 0 ? maxDistance : float.PositiveInfinity;
        }
    }
}
