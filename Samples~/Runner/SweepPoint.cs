namespace Fulcrum.Runner;

/// <summary>One row of sweep.csv: a solver setting and what it measured. Null columns do not apply (written empty).</summary>
sealed record SweepPoint(
    SolverType Solver, int Iterations, int Substeps, float Dt, double MsPerStep,
    float MaxPenetration, float? MaxJointError, float? ReferenceError, float EnergyDrift, float? VolumeError, string SoftSolver = "")
{
    public const string Header = "solver,iterations,substeps,dt,msPerStep,maxPenetration,maxJointError,referenceError,energyDrift,volumeError,softSolver";
}
