namespace Fulcrum
{
    /// <summary>The constraint solver a world uses.</summary>
    public enum SolverType : byte
    {
        /// <summary>Projected Gauss-Seidel: velocity iterations, then position correction.</summary>
        Pgs = 0,
        /// <summary>Temporal Gauss-Seidel: substeps with a biased solve and an unbiased relax.</summary>
        Tgs = 1,
    }
}
