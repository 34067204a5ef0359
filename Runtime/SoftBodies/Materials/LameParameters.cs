using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The two Lame parameters of an isotropic material, Pa. <see cref="Mu"/> is the shear
    /// modulus; <see cref="Lambda"/> the first Lame parameter.
    /// </summary>
    public readonly struct LameParameters : IEquatable<LameParameters>
    {
        /// <summary>Shear modulus mu, Pa.</summary>
        public readonly float Mu;
        /// <summary>First Lame parameter lambda, Pa.</summary>
        public readonly float Lambda;

        /// <summary>Builds the pair from mu and lambda (Pa).</summary>
        public LameParameters(float mu, float lambda)
        {
            Mu = mu;
            Lambda = lambda;
        }

        /// <summary>
        /// Linear elasticity: mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)).
        /// The classic Neo-Hookean energy linearises to exactly these, so it uses them as they are.
        /// Computed in double: near nu = 0.5 the denominator cancels.
        /// </summary>
        public static LameParameters FromYoungPoisson(float youngsModulus, float poissonRatio)
        {
            double e = youngsModulus, nu = poissonRatio;
            return new LameParameters((float)(e / (2 * (1 + nu))), (float)(e * nu / ((1 + nu) * (1 - 2 * nu))));
        }

        /// <summary>
        /// The parameters to put into the stable Neo-Hookean energy so that it linearises to a
        /// material with the given linear Lame parameters. Expanding
        /// Psi = mu/2 (I_C - 3) + lambda/2 (J - alpha)^2 - mu/2 ln(I_C + 1) to second order in a
        /// small symmetric strain e (t = tr e, s = e:e; I_C = 3 + 2t + s, J = 1 + t + (t^2 - s)/2)
        /// gives Psi = (3 mu / 4) s + (lambda/2 - 5 mu / 16) t^2, the linear terms cancelling for
        /// alpha = 1 + 3 mu / (4 lambda). Matching mu_L s + lambda_L/2 t^2 gives
        /// mu = 4/3 mu_L and lambda = lambda_L + 5/6 mu_L (Smith, de Goes, Kim 2018, section 3.4).
        /// </summary>
        public static LameParameters ForStableNeoHookean(in LameParameters linear) =>
            new LameParameters(4f / 3f * linear.Mu, linear.Lambda + 5f / 6f * linear.Mu);

        /// <summary>Young's modulus E = mu (3 lambda + 2 mu) / (lambda + mu) of linear Lame parameters, Pa.</summary>
        public float YoungsModulus => (float)((double)Mu * (3.0 * Lambda + 2.0 * Mu) / ((double)Lambda + Mu));

        /// <summary>Poisson ratio nu = lambda / (2 (lambda + mu)) of linear Lame parameters.</summary>
        public float PoissonRatio => (float)(Lambda / (2.0 * ((double)Lambda + Mu)));

        /// <inheritdoc/>
        public bool Equals(LameParameters other) => Mu == other.Mu && Lambda == other.Lambda;

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is LameParameters p && Equals(p);

        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(Mu, Lambda);

        /// <inheritdoc/>
        public override string ToString() => $"(mu={Mu} Pa, lambda={Lambda} Pa)";
    }
}
