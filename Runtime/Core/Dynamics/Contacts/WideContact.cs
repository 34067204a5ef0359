#if NET
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Vector&lt;float&gt;.Count four-point manifolds of one colour, lane by lane: what every
    /// velocity pass of <see cref="ContactSolverWide"/> reads, and nothing else (the rest is in
    /// <see cref="WideImpact"/>). The point slots are ordered by block pair: slots 0-1 are the
    /// first pair, 2-3 the second. Rows keep their angular Jacobians only: the angular velocity
    /// change per unit impulse, I^-1 (r x d), is recomputed in each pass from the gathered inverse
    /// inertia, as Bepu does, because streaming it costs more than the multiply (the passes are
    /// bound by the bytes they read: 240 bytes a manifold, against 540 with those terms stored).
    /// The inverse masses and the softness of the normal rows follow from the gathered bodies too.
    /// </summary>
    internal struct WideContact
    {
        public WidePoint P0, P1, P2, P3;
        /// <summary>K = J M^-1 J^T of the two block pairs (symmetric).</summary>
        public Vector<float> K11a, K12a, K22a, K11b, K12b, K22b;
        /// <summary>The normal; the tangents follow from it (TangentBasis).</summary>
        public WideVector3 Normal;
        public Vector<float> Friction, TwistRadius;
        /// <summary>Patch friction acts at the centroid of the points: its arms from A's and B's centres of mass.</summary>
        public WideVector3 CentroidA, CentroidB;
        public Vector<float> FrictionMass1, FrictionMass2, FrictionImpulse1, FrictionImpulse2;
        public Vector<float> TwistMass, TwistImpulse;
        /// <summary>Bit k set: point slot k has carried a normal impulse in this step (ContactConstraintPoint.MaxNormalImpulse &gt; 0).</summary>
        public Vector<int> Loaded;
    }
}
#endif
