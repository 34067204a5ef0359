using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// A ball joint whose twist axis (<see cref="Joint.axis"/>) may swing within a cone and twist
    /// within a range (a shoulder, a ragdoll limb; Unity's CharacterJoint has the same role with
    /// separate swing limits per axis). Angles in degrees, measured from the build-time pose.
    /// </summary>
    public sealed class ConeTwistJoint : Joint
    {
        float _cone = 45f, _twist = 45f;

        /// <summary>Half-angle of the swing cone, degrees in [0, 180]. Default: 45.</summary>
        public float coneAngle
        {
            get => _cone;
            set { Check(value, nameof(coneAngle)); SetJointField(ref _cone, value, nameof(coneAngle)); }
        }

        /// <summary>Twist limit either way about the axis, degrees in [0, 180]. Default: 45.</summary>
        public float twistAngle
        {
            get => _twist;
            set { Check(value, nameof(twistAngle)); SetJointField(ref _twist, value, nameof(twistAngle)); }
        }

        internal override void Configure(ref JointDef def)
        {
            def.Kind = JointKind.ConeTwist;
            def.ConeDeg = _cone;
            def.TwistDeg = _twist;
        }

        void Check(float v, string field)
        {
            if (!(v >= 0 && v <= 180)) throw new ArgumentException($"{this}: {field} must be in [0, 180] degrees, got {v}.", field);
        }
    }
}
