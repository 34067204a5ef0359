#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>A hinge about <see cref="FulcrumJoint.axis"/> with limits, motor and spring in Unity's units (Unity's HingeJoint).</summary>
    public sealed class FulcrumHingeJoint : FulcrumJoint
    {
        public bool useLimits;
        [Tooltip("Angle limits, degrees in [-180, 180].")] public F.JointLimits limits;
        public bool useMotor;
        [Tooltip("Target speed, degrees/s, and the largest torque, N m.")] public F.JointMotor motor;
        public bool useSpring;
        [Tooltip("Stiffness N m/rad, damper N m s/rad, target angle degrees.")] public F.JointSpring spring;

        /// <summary>The hinge angle, degrees (0 at the pose the joint was enabled in).</summary>
        public float angle => Joint is F.HingeJoint h ? h.angle : 0f;

        /// <summary>The angular speed about the axis, degrees/s.</summary>
        public float velocity => Joint is F.HingeJoint h ? h.velocity : 0f;

        /// <inheritdoc/>
        protected override F.Joint Create(F.Entity shadow) => shadow.AddComponent<F.HingeJoint>();

        /// <inheritdoc/>
        protected override void PushKind(F.Joint j)
        {
            var h = (F.HingeJoint)j;
            h.limits = limits;
            h.useLimits = useLimits;
            h.motor = motor;
            h.useMotor = useMotor;
            h.spring = spring;
            h.useSpring = useSpring;
        }
    }
}
