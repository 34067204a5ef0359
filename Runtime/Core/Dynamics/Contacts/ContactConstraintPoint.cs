namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The rows of one contact point: the normal and two friction rows, the separation the
    /// manifold reported (updated during the step from the bodies' motion) and what restitution
    /// needs. 184 bytes.
    /// </summary>
    internal struct ContactConstraintPoint
    {
        /// <summary>Non-penetration row along the manifold normal; impulse &gt;= 0.</summary>
        public ContactRow Normal;
        /// <summary>Friction along the first tangent.</summary>
        public ContactRow Tangent1;
        /// <summary>Friction along the second tangent.</summary>
        public ContactRow Tangent2;
        /// <summary>Separation at the start of the step, m (negative = penetration).</summary>
        public float Separation;
        /// <summary>Relative normal velocity before the solve, m/s (negative = approaching).</summary>
        public float RelativeVelocity;
        /// <summary>Largest normal impulse of the step: restitution only acts where it is non-zero.</summary>
        public float MaxNormalImpulse;
        /// <summary>Index of the point in its manifold (0..3).</summary>
        public int ManifoldPoint;
    }
}
