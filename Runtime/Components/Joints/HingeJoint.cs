using System;
using Fulcrum.Dynamics;

namespace Fulcrum.Components
{
    /// <summary>Limits of a <see cref="HingeJoint"/>, degrees (Unity's JointLimits).</summary>
    [Serializable]
    public struct JointLimits
    {
        /// <summary>Lower angle, degrees in [-180, 180].</summary>
        public float min;
        /// <summary>Upper angle, degrees in [-180, 180], &gt;= min.</summary>
        public float max;
    }

    /// <summary>A motor of a <see cref="HingeJoint"/> (Unity's JointMotor).</summary>
    [Serializable]
    public struct JointMotor
    {
        /// <summary>Target angular speed of this body relative to the connected one, degrees/s.</summary>
        public float targetVelocity;
        /// <summary>The largest torque the motor may use, N m (&gt;= 0).</summary>
        public float force;
    }

    /// <summary>
    /// A hinge about <see cref="Joint.axis"/> through <see cref="Joint.anchor"/>, with optional
    /// limits, motor and spring (Unity's HingeJoint). <see cref="angle"/> is 0 at the pose the
    /// joint was built in.
    /// </summary>
    public sealed partial class HingeJoint : Joint
    {
        bool _useLimits, _useMotor;
        JointLimits _limits;
        JointMotor _motor;

        /// <summary>Whether <see cref="limits"/> apply. Default: false.</summary>
        public bool useLimits
        {
            get => _useLimits;
            set { ThrowIfStepping(nameof(useLimits)); _useLimits = value; PushLimits(); }
        }

        /// <summary>The angle limits (used when <see cref="useLimits"/>).</summary>
        public JointLimits limits
        {
            get => _limits;
            set
            {
                if (!(value.min >= -180 && value.min <= value.max && value.max <= 180))
                    throw new ArgumentException($"{this}: limits must satisfy -180 <= min <= max <= 180, got [{value.min}, {value.max}].", nameof(limits));
                ThrowIfStepping(nameof(limits));
                _limits = value;
                PushLimits();
            }
        }

        /// <summary>Whether <see cref="motor"/> drives the hinge. Default: false.</summary>
        public bool useMotor
        {
            get => _useMotor;
            set { ThrowIfStepping(nameof(useMotor)); _useMotor = value; PushMotor(); }
        }

        /// <summary>The motor (used when <see cref="useMotor"/>).</summary>
        public JointMotor motor
        {
            get => _motor;
            set
            {
                if (!float.IsFinite(value.targetVelocity)) throw new ArgumentException($"{this}: motor.targetVelocity must be finite, got {value.targetVelocity}.", nameof(motor));
                if (!(float.IsFinite(value.force) && value.force >= 0)) throw new ArgumentException($"{this}: motor.force must be finite and >= 0, got {value.force}.", nameof(motor));
                ThrowIfStepping(nameof(motor));
                _motor = value;
                PushMotor();
            }
        }

        /// <summary>The hinge angle of this body relative to the connected one, degrees (0 at the build pose).</summary>
        public float angle => IsBuilt ? scene.world.GetJointAngle(joint) * (180f / MathF.PI) : 0f;

        internal override void Configure(ref JointDef def)
        {
            def.Kind = JointKind.Hinge;
            if (_useLimits)
            {
                def.LowerDeg = _limits.min;
                def.UpperDeg = _limits.max;
            }
            if (_useMotor)
            {
                def.MotorSpeed = _motor.targetVelocity * (MathF.PI / 180f);
                def.MaxMotorTorque = _motor.force;
            }
            ConfigureSpring(ref def);
        }

        void PushLimits()
        {
            if (!IsBuilt) return;
            ref JointData j = ref scene.world.Joints.Data[joint.Index];
            const float toRad = MathF.PI / 180f;
            j.Lower = _useLimits ? _limits.min * toRad : float.NegativeInfinity;
            j.Upper = _useLimits ? _limits.max * toRad : float.PositiveInfinity;
        }

        void PushMotor()
        {
            if (!IsBuilt) return;
            if (_useMotor) scene.world.SetJointMotor(joint, _motor.targetVelocity * (MathF.PI / 180f), _motor.force);
            else scene.world.SetJointMotor(joint, 0, 0);
        }
    }
}
