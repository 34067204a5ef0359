using System;

namespace Fulcrum.Runner;

/// <summary>What one run of a scene measured. Null means "does not apply" (shown as "-").</summary>
sealed class RunResult
{
    public required int Steps { get; init; }
    public required double[] StepMs { get; init; }
    public required float MaxPenetration { get; init; }
    /// <summary>Null when the world holds no joints.</summary>
    public float? MaxJointError { get; init; }
    public required float EnergyStart { get; init; }
    public required float EnergyEnd { get; init; }
    /// <summary>max |V/V0 - 1| over the run and the soft bodies; null without soft bodies.</summary>
    public float? VolumeError { get; init; }
    /// <summary>The smallest element volume ratio J seen; null without soft bodies.</summary>
    public float? MinJ { get; init; }
    /// <summary>Largest distance of a centre of mass from its closed-form ballistic path, m; null unless every body flies free.</summary>
    public float? ClosedFormError { get; init; }

    /// <summary>E(end) - E(0), joules.</summary>
    public float EnergyDrift => EnergyEnd - EnergyStart;

    public double MedianMs => Percentile(0.5);
    public double P95Ms => Percentile(0.95);

    double Percentile(double p)
    {
        if (StepMs.Length == 0) return 0;
        double[] sorted = (double[])StepMs.Clone();
        Array.Sort(sorted);
        // Nearest rank: the smallest value with at least p of the samples at or below it.
        int rank = (int)Math.Ceiling(p * sorted.Length) - 1;
        return sorted[Math.Clamp(rank, 0, sorted.Length - 1)];
    }
}
