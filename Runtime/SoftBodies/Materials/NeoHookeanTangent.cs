using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The energy density, first Piola-Kirchhoff stress and its differential (the tangent) of
    /// both Neo-Hookean models in double precision, F and P row-major in 9 doubles: what the
    /// Newton solvers (the static reference <see cref="StaticEquilibrium"/> and the runtime
    /// <see cref="ImplicitNewtonSolver"/>) assemble their gradients and Hessians from.
    /// Stable (Smith, de Goes, Kim 2018): Psi = mu/2 (I_C - 3) - mu/2 ln((I_C + 1)/4) + lambda/2 (J - alpha)^2,
    /// P = mu I_C/(I_C+1) F + lambda (J - alpha) cof F. Classic: Psi = mu/2 (I_C - 3) - mu ln J + lambda/2 ln^2 J,
    /// P = mu F + (lambda ln J - mu) F^-T.
    /// </summary>
    internal readonly struct NeoHookeanTangent
    {
        public readonly bool Stable;
        public readonly double Mu, Lambda, Alpha;

        public NeoHookeanTangent(in NeoHookeanMaterial material)
        {
            Stable = material.Model == MaterialModel.StableNeoHookean;
            if (Stable)
            {
                StableNeoHookeanEnergy e = StableNeoHookeanEnergy.Of(material);
                Mu = e.Mu;
                Lambda = e.Lambda;
                Alpha = 1.0 + 0.75 * Mu / Lambda;
            }
            else
            {
                LameParameters l = material.LinearLame;
                Mu = l.Mu;
                Lambda = l.Lambda;
                Alpha = 1.0;
            }
        }

        /// <summary>The energy density, J/m^3 (zero at rest; +infinity for an inverted element of the classic model).</summary>
        public double Psi(ReadOnlySpan<double> f)
        {
            double ic = 0;
            for (int k = 0; k < 9; k++) ic += f[k] * f[k];
            double j = Det(f);
            if (Stable)
                return 0.5 * Mu * (ic - 3) + 0.5 * Lambda * (j - Alpha) * (j - Alpha) - 0.5 * Mu * Math.Log((ic + 1) / 4)
                    - 0.5 * Lambda * (1 - Alpha) * (1 - Alpha);
            if (j <= 0) return double.PositiveInfinity;
            double lj = Math.Log(j);
            return 0.5 * Mu * (ic - 3) - Mu * lj + 0.5 * Lambda * lj * lj;
        }

        /// <summary>First Piola-Kirchhoff stress P = dPsi/dF (row-major).</summary>
        public void Stress(ReadOnlySpan<double> f, Span<double> p)
        {
            double ic = 0;
            for (int k = 0; k < 9; k++) ic += f[k] * f[k];
            double j = Det(f);
            Span<double> cof = stackalloc double[9];
            Cofactor(f, cof);
            if (Stable)
            {
                double a = Mu * ic / (ic + 1), c = Lambda * (j - Alpha);
                for (int k = 0; k < 9; k++) p[k] = a * f[k] + c * cof[k];
            }
            else
            {
                double c = (Lambda * Math.Log(j) - Mu) / j;   // (lambda ln J - mu) F^-T, F^-T = cof / J
                for (int k = 0; k < 9; k++) p[k] = Mu * f[k] + c * cof[k];
            }
        }

        /// <summary>
        /// The whole tangent C[(i,j),(l,q)] = dP_ij / dF_lq at F into <paramref name="c"/> (81 values, at 9 ij + lq),
        /// one directional derivative (<see cref="StressDifferential"/>) per unit dF.
        /// </summary>
        public void Tangent(ReadOnlySpan<double> f, Span<double> c)
        {
            Span<double> unit = stackalloc double[9];
            Span<double> dp = stackalloc double[9];
            for (int lq = 0; lq < 9; lq++)
            {
                unit.Clear();
                unit[lq] = 1;
                StressDifferential(f, unit, dp);
                for (int ij = 0; ij < 9; ij++) c[9 * ij + lq] = dp[ij];
            }
        }

        /// <summary>dP along dF. cof is quadratic in F, so its differential is exactly (cof(F + dF) - cof(F - dF)) / 2.</summary>
        public void StressDifferential(ReadOnlySpan<double> f, ReadOnlySpan<double> df, Span<double> dp)
        {
            double ic = 0, fdf = 0;
            for (int k = 0; k < 9; k++) { ic += f[k] * f[k]; fdf += f[k] * df[k]; }
            double j = Det(f);
            Span<double> cof = stackalloc double[9];
            Span<double> plus = stackalloc double[9];
            Span<double> minus = stackalloc double[9];
            Span<double> tmp = stackalloc double[9];
            Cofactor(f, cof);
            for (int k = 0; k < 9; k++) tmp[k] = f[k] + df[k];
            Cofactor(tmp, plus);
            for (int k = 0; k < 9; k++) tmp[k] = f[k] - df[k];
            Cofactor(tmp, minus);
            double dj = 0;
            for (int k = 0; k < 9; k++) dj += cof[k] * df[k];
            if (Stable)
            {
                double a = Mu * ic / (ic + 1), b = 2 * Mu * fdf / ((ic + 1) * (ic + 1)), c = Lambda * (j - Alpha);
                for (int k = 0; k < 9; k++) dp[k] = a * df[k] + b * f[k] + Lambda * dj * cof[k] + c * 0.5 * (plus[k] - minus[k]);
            }
            else
            {
                // P = mu F + (lambda ln J - mu) G, G = cof / J; dG = dcof / J - cof dJ / J^2.
                double lj = Math.Log(j), c = Lambda * lj - Mu;
                for (int k = 0; k < 9; k++)
                {
                    double g = cof[k] / j;
                    double dg = 0.5 * (plus[k] - minus[k]) / j - cof[k] * dj / (j * j);
                    dp[k] = Mu * df[k] + Lambda * (dj / j) * g + c * dg;
                }
            }
        }

        /// <summary>det of a row-major 3 x 3.</summary>
        public static double Det(ReadOnlySpan<double> a) =>
            a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);

        /// <summary>cof a = det(a) a^-T, row-major.</summary>
        public static void Cofactor(ReadOnlySpan<double> a, Span<double> c)
        {
            c[0] = a[4] * a[8] - a[5] * a[7]; c[1] = a[5] * a[6] - a[3] * a[8]; c[2] = a[3] * a[7] - a[4] * a[6];
            c[3] = a[2] * a[7] - a[1] * a[8]; c[4] = a[0] * a[8] - a[2] * a[6]; c[5] = a[1] * a[6] - a[0] * a[7];
            c[6] = a[1] * a[5] - a[2] * a[4]; c[7] = a[2] * a[3] - a[0] * a[5]; c[8] = a[0] * a[4] - a[1] * a[3];
        }
    }
}
