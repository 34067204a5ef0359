using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Plastic flow of a tet soft body: where an element's deviatoric (shape-changing)
    /// logarithmic strain exceeds <see cref="YieldStrain"/>, its rest shape moves toward the
    /// current shape at <see cref="FlowRate"/>, so a pressed blob keeps a dent. Volume is kept
    /// (the flow is traceless), and the total plastic strain is capped at <see cref="MaxStrain"/>.
    /// <see cref="None"/> (the default) turns it off.
    /// </summary>
    public struct SoftPlasticity
    {
        /// <summary>Deviatoric Hencky strain (|dev ln U|, dimensionless) below which the material is elastic. &gt;= 0. Default: 0.1.</summary>
        public float YieldStrain;
        /// <summary>Fraction of the strain above yield that flows into the rest shape per second, 1/s. 0 disables plasticity. Default: 0 (off).</summary>
        public float FlowRate;
        /// <summary>The largest plastic strain an element may accumulate (|ln Fp|). &gt; 0. Default: 1.</summary>
        public float MaxStrain;

        /// <summary>No plasticity.</summary>
        public static SoftPlasticity None => new SoftPlasticity { YieldStrain = 0.1f, FlowRate = 0f, MaxStrain = 1f };

        /// <summary>Plasticity with the given yield strain and flow rate (1/s).</summary>
        public static SoftPlasticity Flow(float yieldStrain, float flowRate, float maxStrain = 1f) =>
            new SoftPlasticity { YieldStrain = yieldStrain, FlowRate = flowRate, MaxStrain = maxStrain };

        /// <summary>True when plastic flow is on.</summary>
        public readonly bool Enabled => FlowRate > 0;

        /// <summary>Throws an <see cref="ArgumentException"/> naming the first bad field.</summary>
        public readonly void Validate()
        {
            Mathematics.Validate.NonNegative(YieldStrain, "softBody.Plasticity.YieldStrain");
            Mathematics.Validate.NonNegative(FlowRate, "softBody.Plasticity.FlowRate");
            if (Enabled) Mathematics.Validate.Positive(MaxStrain, "softBody.Plasticity.MaxStrain");
        }
    }
}
