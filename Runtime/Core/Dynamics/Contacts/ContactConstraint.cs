using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The solver's view of one contact manifold: the two solver bodies, the shared frame
    /// (normal from A to B and two tangents), the combined material, the softness of its
    /// normal rows, the range of its points in the point array, and its friction: two tangent
    /// rows at the centroid of the points and a twist row about the normal (patch friction).
    /// Built at the start of every step from the collision stage's manifold, written back to
    /// it at the end.
    /// </summary>
    internal struct ContactConstraint
    {
        /// <summary>Solver body index of A (0 = fixed).</summary>
        public int BodyA;
        /// <summary>Solver body index of B (0 = fixed).</summary>
        public int BodyB;
        /// <summary>First point in the point array.</summary>
        public int FirstPoint;
        /// <summary>Number of points (1..4).</summary>
        public int PointCount;
        /// <summary>Index of the manifold in the contact set (for the write-back).</summary>
        public int Manifold;
        /// <summary>
        /// Per-axis 1/m of A and B (0 for fixed bodies, 0 along a locked translation axis, see
        /// <see cref="AxisLocks"/>); the three components are equal for a body without locks.
        /// </summary>
        public Vector3 InvMassA, InvMassB;
        /// <summary>Unit normal from A to B.</summary>
        public Vector3 Normal;
        /// <summary>Tangents with t1 x t2 = normal.</summary>
        public Vector3 Tangent1, Tangent2;
        /// <summary>Coulomb friction coefficient.</summary>
        public float Friction;
        /// <summary>Coefficient of restitution.</summary>
        public float Restitution;
        /// <summary>Rolling resistance: the largest rolling torque per newton of normal force, m.</summary>
        public float RollingFriction;
        /// <summary>Friction along the first tangent at the centroid of the points.</summary>
        public ContactRow Friction1;
        /// <summary>Friction along the second tangent at the centroid.</summary>
        public ContactRow Friction2;
        /// <summary>Twist friction about the normal: effective mass and accumulated impulse (N m s).</summary>
        public float TwistMass, TwistImpulse;
        /// <summary>Mean distance of the points from their centroid, m: the lever arm of twist friction.</summary>
        public float TwistRadius;
        /// <summary>Accumulated rolling impulses about the two tangents, N m s.</summary>
        public float RollingImpulse1, RollingImpulse2;
        /// <summary>Effective masses of the rolling rows.</summary>
        public float RollingMass1, RollingMass2;
        /// <summary>Softness of the normal rows (contact softness, stiffer against fixed bodies).</summary>
        public Softness Softness;
        /// <summary>Block solving: the first pair of points (or -1), see <see cref="ContactBlockSolver"/>.</summary>
        public ContactBlockPair Block0;
        /// <summary>Block solving: the second pair of points of a four-point manifold (or -1).</summary>
        public ContactBlockPair Block1;
    }
}
