using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Components
{
    /// <summary>
    /// One contact's force in one step, for haptic devices: written by the thread that steps
    /// the world, read from <see cref="PhysicsBridge.Haptics"/> at the device's own rate.
    /// </summary>
    public struct ContactForceSample
    {
        /// <summary>Simulated time at the end of the step, seconds.</summary>
        public double Time;
        /// <summary>The world step.</summary>
        public long StepIndex;
        /// <summary>Begin, persist or end (ends carry zero force: the release).</summary>
        public ContactEventKind Kind;
        /// <summary>First entity's proxy.</summary>
        public ProxyHandle ProxyA;
        /// <summary>Second entity's proxy.</summary>
        public ProxyHandle ProxyB;
        /// <summary>Average contact point, world, metres.</summary>
        public Vector3 Point;
        /// <summary>World normal from A to B.</summary>
        public Vector3 Normal;
        /// <summary>Mean normal force over the step on B (A feels the opposite), N: the normal impulse divided by the step.</summary>
        public Vector3 Force;
        /// <summary>Relative velocity of B with respect to A at the contact, m/s (for vibration cues).</summary>
        public Vector3 RelativeVelocity;
    }
}
