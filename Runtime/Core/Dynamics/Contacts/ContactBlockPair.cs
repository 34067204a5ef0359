namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Two normal rows of one manifold solved together by <see cref="ContactBlockSolver"/>:
    /// the point indices (absolute, in the point array; -1 when unused) and the 2x2 matrix
    /// K = J M^-1 J^T of their normal rows.
    /// </summary>
    internal struct ContactBlockPair
    {
        /// <summary>First point, or -1 when the pair is unused.</summary>
        public int I;
        /// <summary>Second point.</summary>
        public int J;
        /// <summary>K entries (symmetric).</summary>
        public float K11, K12, K22;

        /// <summary>An unused pair.</summary>
        public static ContactBlockPair None => new ContactBlockPair { I = -1, J = -1 };

        /// <summary>True when the pair is solved as a block.</summary>
        public readonly bool IsUsed => I >= 0;
    }
}
