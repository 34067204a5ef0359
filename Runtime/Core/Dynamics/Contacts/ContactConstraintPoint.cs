namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The normal row of one contact point, the separation the manifold reported (carried
    /// through the step from the bodies' motion) and what restitution needs. 80 bytes.
    /// Friction lives on the manifold (<see cref="ContactConstraint"/>).
    /// </summary>
    internal struct ContactConstraintPoint
    {
        /// <summary>Non-penetration row along the manifold normal; impulse &gt;= 0.</summary>
        public ContactRow Normal;
        /// <summary>Separation at the start of the step, m (negative = penetration).</summary>
        public float Separation;
        /// <summary>Approach speed for restitution, m/s (negative = approaching); see <see cref="ContactSolver.RecordImpact"/>.</summary>
        public float RelativeVelocity;
        /// <summary>Largest normal impulse of the step: restitution only acts where it is non-zero.</summary>
        public float MaxNormalImpulse;
        /// <summary>Index of the point in its manifold (0..3).</summary>
        public int ManifoldPoint;
        /// <summary>Sum of the normal impulse at the end of each substep so far: what the substeps applied.</summary>
        public float Applied;
        /// <summary>The normal impulse at the end of the last substep (restitution adds to it afterwards).</summary>
        public float LastSubstep;
    }
}
