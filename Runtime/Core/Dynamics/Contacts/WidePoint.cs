#if NET
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>One point slot of a <see cref="WideContact"/>: its normal row's angular Jacobians, separation and impulse.</summary>
    internal struct WidePoint
    {
        /// <summary>rA x n and rB x n.</summary>
        public WideVector3 AngularA, AngularB;
        /// <summary>Separation at the start of the step, m.</summary>
        public Vector<float> Separation;
        /// <summary>Accumulated normal impulse, N s.</summary>
        public Vector<float> Impulse;
        /// <summary>Separation at the pose of the current substep, m: set by the warm start for that substep's biased passes.</summary>
        public Vector<float> Current;
    }
}
#endif
