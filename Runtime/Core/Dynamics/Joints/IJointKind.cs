namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The passes of one joint kind, implemented by a struct per kind
    /// (<c>&lt;Kind&gt;JointSolver</c>) that <see cref="JointSolver"/> runs generically, so each
    /// kind compiles to direct calls. Every pass starts with <see cref="Setup"/>, which rebuilds
    /// the kind's rows from the joint's current geometry (and keeps in the struct what the pass
    /// needs: axes, angles, which rows are active); then exactly one of the other methods runs.
    /// </summary>
    internal interface IJointKind
    {
        /// <summary>Rebuilds the rows from <paramref name="g"/>; with <paramref name="mass"/>, their effective masses.</summary>
        void Setup(ref JointData j, in SolverBody a, in SolverBody b, in JointGeometry g, bool mass);

        /// <summary>Applies the accumulated impulses (warm start).</summary>
        void WarmStart(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g);

        /// <summary>One velocity iteration; with <paramref name="useBias"/> the rows are soft and remove the position error.</summary>
        void Solve(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, in JointSolver.StepParameters p, bool useBias);

        /// <summary>One position iteration (non-linear Gauss-Seidel) removing the fraction <paramref name="beta"/> of the error.</summary>
        void SolvePosition(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, float beta, float maxC);

        /// <summary>Writes force, torque, stress and position error (<see cref="JointSolver.Report"/>).</summary>
        void Report(ref JointData j, in JointGeometry g, in JointSolver.StepParameters p);
    }
}
