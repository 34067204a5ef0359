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
        [Tooltip("Half-angle of the swing cone, degrees in [0, 180].")] public float swingLimit = 45f;
        [Tooltip("Twist either way about the axis, degrees in [0, 180].")] public float twistLimit = 45f;

        /// <inheritdoc/>
        protected override F.Joint Create(F.Entity shadow) => shadow.AddComponent<F.ConeTwistJoint>();

        /// <inheritdoc/>
        protected override void PushKind(F.Joint j)
        {
            var c = (F.ConeTwistJoint)j;
            c.coneAngle = Mathf.Clamp(swingLimit, 0f, 180f);
            c.twistAngle = Mathf.Clamp(twistLimit, 0f, 180f);
        }
    }
}
