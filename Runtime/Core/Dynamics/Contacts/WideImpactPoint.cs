#if NET
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>One point slot of a <see cref="WideImpact"/> (see <see cref="ContactConstraintPoint"/>).</summary>
    internal struct WideImpactPoint
    {
        /// <summary>1 / K of the normal row.</summary>
        public Vector<float> EffectiveMass;
        /// <summary>Approach speed for restitution, m/s (ContactConstraintPoint.RelativeVelocity).</summary>
        public Vector<float> RelativeVelocity;
        /// <summary>Sum of the normal impulse at the end of each substep so far.</summary>
        public Vector<float> Applied;
        /// <summary>The normal impulse at the end of the last substep.</summary>
        public Vector<float> LastSubstep;
    }
}
#endif
