using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// An isotropic hyperelastic material, in the terms of the scene file's soft-body
    /// <c>material</c> entry: <c>{"model", "youngsModulus", "poissonRatio", "density"}</c>.
    /// E and nu are the small-strain (linear) constants; each model maps them to the Lame
    /// parameters of its own energy (<see cref="EnergyLame"/>) so that both reproduce E and nu
    /// at small strain. Presets with sources are in <see cref="MaterialPresets"/>.
    /// </summary>
    public struct NeoHookeanMaterial
    {
        /// <summary>The energy. Default: <see cref="MaterialModel.StableNeoHookean"/>.</summary>
        public MaterialModel Model;
        /// <summary>Young's modulus E at small strain, Pa (&gt; 0). Default: 1e5 Pa.</summary>
        public float YoungsModulus;
        /// <summary>Poisson ratio nu at small strain, in (-1, 0.5); the classic model needs nu &gt; 0. Default: 0.45.</summary>
        public float PoissonRatio;
        /// <summary>Mass density, kg/m^3 (&gt; 0). Default: 1000 kg/m^3.</summary>
        public float Density;

        /// <summary>A stable Neo-Hookean material with E = 1e5 Pa, nu = 0.45, 1000 kg/m^3 (the scene file's example jelly).</summary>
        public static NeoHookeanMaterial Default => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, 0.45f, 1000f);

        /// <summary>Builds a material from the small-strain Young's modulus (Pa), Poisson ratio and density (kg/m^3).</summary>
        public NeoHookeanMaterial(MaterialModel model, float youngsModulus, float poissonRatio, float density)
        {
            Model = model;
            YoungsModulus = youngsModulus;
            PoissonRatio = poissonRatio;
            Density = density;
        }

        /// <summary>
        /// Builds a material from the small-strain (linear) Lame parameters mu and lambda, Pa.
        /// They are converted to E and nu, so the model's own mapping still applies.
        /// </summary>
        public static NeoHookeanMaterial FromLame(MaterialModel model, float mu, float lambda, float density)
        {
            Mathematics.Validate.Positive(mu, "material.Mu");
            Mathematics.Validate.Finite(lambda, "material.Lambda");
            if (!(lambda + 2f / 3f * mu > 0))
                throw new ArgumentException($"material.Lambda must give a positive bulk modulus (lambda + 2 mu / 3 > 0), got lambda={lambda}, mu={mu}.", "material.Lambda");
            var linear = new LameParameters(mu, lambda);
            return new NeoHookeanMaterial(model, linear.YoungsModulus, linear.PoissonRatio, density);
        }

        /// <summary>The small-strain Lame parameters of E and nu.</summary>
        public readonly LameParameters LinearLame => LameParameters.FromYoungPoisson(YoungsModulus, PoissonRatio);

        /// <summary>
        /// The Lame parameters that go into the model's energy: the linear ones for the classic
        /// model, <see cref="LameParameters.ForStableNeoHookean"/> of them for the stable one.
        /// </summary>
        public readonly LameParameters EnergyLame =>
            Model == MaterialModel.StableNeoHookean ? LameParameters.ForStableNeoHookean(LinearLame) : LinearLame;

        /// <summary>Throws an <see cref="ArgumentException"/> naming the first bad field.</summary>
        public readonly void Validate()
        {
            if (Model != MaterialModel.StableNeoHookean && Model != MaterialModel.NeoHookean)
                throw new ArgumentException($"material.Model must be StableNeoHookean or NeoHookean, got {Model}.", "material.Model");
            Mathematics.Validate.Positive(YoungsModulus, "material.YoungsModulus");
            if (!(PoissonRatio > -1f && PoissonRatio < 0.5f))
                throw new ArgumentException($"material.PoissonRatio must be in (-1, 0.5), got {PoissonRatio}.", "material.PoissonRatio");
            // The classic energy's volume term lambda/2 (ln J - mu/lambda)^2 is convex only for lambda > 0.
            if (Model == MaterialModel.NeoHookean && !(PoissonRatio > 0f))
                throw new ArgumentException($"material.PoissonRatio must be > 0 for the neo-hookean model (its lambda must be positive), got {PoissonRatio}; use stable-neo-hookean for nu <= 0.", "material.PoissonRatio");
            Mathematics.Validate.Positive(Density, "material.Density");
        }

        /// <summary>The scene file's name of a model: "stable-neo-hookean" or "neo-hookean".</summary>
        public static string ModelName(MaterialModel model) => model == MaterialModel.NeoHookean ? "neo-hookean" : "stable-neo-hookean";

        /// <summary>Parses a scene file model name; throws an <see cref="ArgumentException"/> naming material.model otherwise.</summary>
        public static MaterialModel ParseModel(string name)
        {
            if (name == "stable-neo-hookean") return MaterialModel.StableNeoHookean;
            if (name == "neo-hookean") return MaterialModel.NeoHookean;
            throw new ArgumentException($"material.model must be \"stable-neo-hookean\" or \"neo-hookean\", got \"{name}\".", "material.model");
        }

        /// <inheritdoc/>
        public override readonly string ToString() =>
            $"{ModelName(Model)}(E={YoungsModulus} Pa, nu={PoissonRatio}, rho={Density} kg/m^3)";
    }
}
