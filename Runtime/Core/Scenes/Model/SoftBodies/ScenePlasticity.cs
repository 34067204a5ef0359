namespace Fulcrum.Scenes
{
    /// <summary>
    /// The <c>plasticity</c> of a soft body (an extension of <c>fulcrum-scene/1</c>):
    /// <c>{"yieldStrain": 0.05, "flowRate": 5, "maxStrain": 1}</c>. Strain beyond the yield
    /// flows into the rest shape, so a pressed blob keeps a dent.
    /// </summary>
    public sealed class ScenePlasticity
    {
        /// <summary><c>yieldStrain</c>: deviatoric Hencky strain below which the material is elastic, &gt;= 0. Default: 0.1.</summary>
        public float YieldStrain { get; set; } = 0.1f;

        /// <summary><c>flowRate</c>: fraction of the strain above yield that flows per second, 1/s, &gt; 0. Required.</summary>
        public float FlowRate { get; set; }

        /// <summary><c>maxStrain</c>: the largest plastic strain an element may accumulate, &gt; 0. Default: 1.</summary>
        public float MaxStrain { get; set; } = 1f;
    }
}
