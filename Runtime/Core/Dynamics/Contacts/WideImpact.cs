#if NET
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// What restitution and the report of applied impulses need for the manifolds of a
    /// <see cref="WideContact"/>, kept apart so that the solve passes do not stream it.
    /// </summary>
    internal struct WideImpact
    {
        public WideImpactPoint P0, P1, P2, P3;
        /// <summary>Coefficient of restitution.</summary>
        public Vector<float> Restitution;
    }
}
#endif
