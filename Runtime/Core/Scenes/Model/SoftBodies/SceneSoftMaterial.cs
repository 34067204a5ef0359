namespace Fulcrum.Scenes
{
    /// <summary>
    /// The <c>material</c> of a soft body: a model and either Young's modulus and Poisson's
    /// ratio, or the Lame constants mu and lambda (one pair, not both).
    /// </summary>
    public sealed class SceneSoftMaterial
    {
        /// <summary><c>model</c>. Default: stable-neo-hookean.</summary>
        public SceneSoftModel Model { get; set; } = SceneSoftModel.StableNeoHookean;

        /// <summary><c>youngsModulus</c> E, Pa, &gt; 0; with <see cref="PoissonRatio"/>.</summary>
        public float? YoungsModulus { get; set; }

        /// <summary><c>poissonRatio</c> nu, in (-1, 0.5); with <see cref="YoungsModulus"/>.</summary>
        public float? PoissonRatio { get; set; }

        /// <summary><c>mu</c>: the shear modulus, Pa, &gt; 0; with <see cref="Lambda"/>.</summary>
        public float? Mu { get; set; }

        /// <summary><c>lambda</c>: Lame's first parameter, Pa; with <see cref="Mu"/>.</summary>
        public float? Lambda { get; set; }

        /// <summary><c>density</c>, kg/m^3, &gt; 0. Default: 1000.</summary>
        public float Density { get; set; } = 1000f;
    }
}
