#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>A hinge about <see cref="FulcrumJoint.axis"/> with limits, motor and spring in Unity's units (Unity's HingeJoint).</summary>
    public sealed class FulcrumHingeJoint : FulcrumJoint
    {
        [SerializeField] bool m_UseLimits;
        [SerializeField, Tooltip("Angle limits, degrees in [-180, 180].")] F.JointLimits m_Limits;
        [SerializeField] bool m_UseMotor;
        [SerializeField, Tooltip("Target speed, degrees/s, and the largest torque, N m.")] F.JointMotor m_Motor;
        [SerializeField] bool m_UseSpring;
        [SerializeField, Tooltip("Stiffness N m/rad, damper N m s/rad, target angle degrees.")] F.JointSpring m_Spring;

        /// <summary>Whether <see cref="limits"/> apply.</summary>
        public bool useLimits { get => m_UseLimits; set { m_UseLimits = value; Push(); } }
        /// <summary>Angle limits, degrees.</summary>
        public F.JointLimits limits { get => m_Limits; set { m_Limits = value; Push(); } }
        /// <summary>Whether <see cref="motor"/> drives the hinge.</summary>
        public bool useMotor { get => m_UseMotor; set { m_UseMotor = value; Push(); } }
        /// <summary>The motor: target speed (degrees/s) and largest torque (N m).</summary>
        public F.JointMotor motor { get => m_Motor; set { m_Motor = value; Push(); } }
        /// <summary>Whether <see cref="spring"/> acts.</summary>
        public bool useSpring { get => m_UseSpring; set { m_UseSpring = value; Push(); } }
        /// <summary>The spring in Unity's units (see <see cref="F.HingeJoint.spring"/>).</summary>
        public F.JointSpring spring { get => m_Spring; set { m_Spring = value; Push(); } }

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
            if (m_UseLimits) h.limits = m_Limits;
            h.useLimits = m_UseLimits;
            if (m_UseMotor) h.motor = m_Motor;
            h.useMotor = m_UseMotor;
            if (m_UseSpring) h.spring = m_Spring;
            h.useSpring = m_UseSpring;
        }
    }
}
