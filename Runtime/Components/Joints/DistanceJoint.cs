using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// Keeps the anchors between <see cref="minDistance"/> and <see cref="maxDistance"/>, with an
    /// optional spring toward the build-time distance (Unity's SpringJoint, and a rope or rod).
    /// Departure from Unity: the spring is given as a frequency (<see cref="spring"/>, Hz) and a
    /// damping ratio (<see cref="damper"/>, 1 = critical), which stay stable for any mass, not as
    /// N/m and N s/m. As in Unity, auto-configured anchors start together (a zero length):
    /// set <see cref="Joint.connectedAnchor"/> (say, the connected body's centre) for a rope or rod.
    /// </summary>
    public sealed class DistanceJoint : Joint
    {
        float _min = -1, _max = -1, _spring, _damper;

        /// <summary>Shortest distance, metres; negative = the distance at build time (none with a spring). Default: -1.</summary>
        public float minDistance
        {
            get => _min;
            set { Check(value, nameof(minDistance)); SetJointField(ref _min, value, nameof(minDistance)); }
        }

        /// <summary>Longest distance, metres (infinity allowed); negative = the distance at build time (none with a spring). Default: -1.</summary>
        public float maxDistance
        {
            get => _max;
            set { if (!float.IsPositiveInfinity(value)) Check(value, nameof(maxDistance)); SetJointField(ref _max, value, nameof(maxDistance)); }
        }

        /// <summary>Spring frequency toward the build-time distance, Hz (0 = rigid limits only). Default: 0.</summary>
        public float spring
        {
            get => _spring;
            set { FieldCheck.NonNegative(value, this, nameof(spring)); SetJointField(ref _spring, value, nameof(spring)); }
        }

        /// <summary>Spring damping ratio (1 = critical). Default: 0.</summary>
        public float damper
        {
            get => _damper;
            set { FieldCheck.NonNegative(value, this, nameof(damper)); SetJointField(ref _damper, value, nameof(damper)); }
        }

        internal override void Configure(ref JointDef def)
        {
            def.Kind = JointKind.Distance;
            def.MinLength = _min;
            def.MaxLength = _max;
            def.StiffnessHz = _spring;
            def.Damping = _damper;
        }

        void Check(float v, string field)
        {
            if (!float.IsFinite(v)) throw new ArgumentException($"{this}: {field} must be finite (or negative for the build-time distance), got {v}.", field);
        }
    }
}
