#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// A ball joint with a swing cone and a twist range about <see cref="FulcrumJoint.axis"/>, for
    /// ragdoll limbs (Unity's CharacterJoint, on <see cref="F.ConeTwistJoint"/>). Departure from
    /// Unity: one symmetric swing limit (Unity has swing1/swing2) and one symmetric twist limit
    /// (Unity has low/high), in degrees.
    /// </summary>
    public sealed class FulcrumCharacterJoint : FulcrumJoint
    {
        [SerializeField, Tooltip("Half-angle of the swing cone, degrees in [0, 180].")] float m_SwingLimit = 45f;
        [SerializeField, Tooltip("Twist either way about the axis, degrees in [0, 180].")] float m_TwistLimit = 45f;

        /// <summary>Half-angle of the swing cone, degrees in [0, 180].</summary>
        public float swingLimit { get => m_SwingLimit; set { m_SwingLimit = value; Push(); } }
        /// <summary>Twist either way about the axis, degrees in [0, 180].</summary>
        public float twistLimit { get => m_TwistLimit; set { m_TwistLimit = value; Push(); } }

        /// <inheritdoc/>
        protected override F.Joint Create(F.Entity shadow) => shadow.AddComponent<F.ConeTwistJoint>();

        /// <inheritdoc/>
        protected override void PushKind(F.Joint j)
        {
            var c = (F.ConeTwistJoint)j;
            float cone = Mathf.Clamp(m_SwingLimit, 0f, 180f), twist = Mathf.Clamp(m_TwistLimit, 0f, 180f);
            if (c.coneAngle != cone) c.coneAngle = cone;
            if (c.twistAngle != twist) c.twistAngle = twist;
        }
    }
}
