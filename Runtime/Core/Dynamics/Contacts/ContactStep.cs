namespace Fulcrum.Dynamics
{
    /// <summary>
    /// What every contact row of one step reads and no row changes: the step and substep
    /// lengths, the contact softness (against a moving body and against a fixed one), the
    /// warm-start scale and the settings the passes use. Built once per step by
    /// <see cref="SolverContext"/> and handed to <see cref="ContactSolver"/>,
    /// <see cref="ContactPositionSolver"/> and <c>ContactSolverWide</c> (net10) by reference,
    /// in place of their long argument lists.
    /// </summary>
    internal readonly struct ContactStep
    {
        /// <summary>The step, seconds.</summary>
        public readonly float Dt;
        /// <summary>1 / the substep (the whole step for PGS), 1/s: a speculative gap s may close at s times this.</summary>
        public readonly float InverseH;
        /// <summary>The softness of a normal row between two moving bodies.</summary>
        public readonly Softness Contact;
        /// <summary>The softness of a normal row against a body that cannot move (twice the contact hertz, Box2D v3).</summary>
        public readonly Softness FixedBody;
        /// <summary>The factor on last step's impulses (substep over the previous step; 0 without warm starting).</summary>
        public readonly float WarmScale;
        /// <summary>True when four- and three-point manifolds solve their normal rows in block pairs.</summary>
        public readonly bool Block;
        /// <summary><see cref="WorldSettings.MaxContactPushSpeed"/>, m/s.</summary>
        public readonly float MaxPushSpeed;
        /// <summary><see cref="WorldSettings.LinearSlop"/>, m.</summary>
        public readonly float LinearSlop;
        /// <summary><see cref="WorldSettings.RestitutionThreshold"/>, m/s.</summary>
        public readonly float RestitutionThreshold;

        public ContactStep(float dt, float inverseH, in Softness contact, in Softness fixedBody, float warmScale, bool block,
            float maxPushSpeed, float linearSlop, float restitutionThreshold)
        {
            Dt = dt;
            InverseH = inverseH;
            Contact = contact;
            FixedBody = fixedBody;
            WarmScale = warmScale;
            Block = block;
            MaxPushSpeed = maxPushSpeed;
            LinearSlop = linearSlop;
            RestitutionThreshold = restitutionThreshold;
        }

        /// <summary>The largest correction of one position pass (PGS), m: the push speed over the step.</summary>
        public float MaxCorrection => MaxPushSpeed * Dt;
    }
}
