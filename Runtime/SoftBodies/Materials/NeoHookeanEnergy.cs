using System;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Classic compressible Neo-Hookean energy Psi = mu/2 (I_C - 3) - mu ln J + lambda/2 (ln J)^2
    /// (e.g. Bonet and Wood, "Nonlinear Continuum Mechanics for Finite Element Analysis", eq. 6.28),
    /// with the linear Lame parameters of E and nu.
    /// <para>
    /// J &lt;= 0: ln J does not exist there, and the true energy goes to infinity as J -&gt; 0+.
    /// Below <see cref="MinJ"/> ln J is replaced by its tangent line
    /// L(J) = ln MinJ + (J - MinJ) / MinJ, which joins it with the same value and slope (C1).
    /// The energy then stays finite for every F, is quadratic in J below MinJ, and its
    /// gradient keeps pushing J up (dPsi/dJ = (lambda L - mu) / MinJ &lt; 0 there), so an
    /// inverted element recovers instead of producing NaN. Above MinJ it is exactly the classic energy.
    /// </para>
    /// As XPBD constraints, both zero at rest: Psi = mu/2 C_D^2 + lambda/2 C_H^2 with
    /// C_D = sqrt(I_C - 3 - 2 L(J)) and C_H = L(J). C_D^2 &gt;= 0 for every F: for J &gt; 0,
    /// I_C &gt;= 3 J^(2/3) (the mean of the squared singular values is at least their geometric
    /// mean) and 3 J^(2/3) - 3 - 2 ln J &gt;= 0; below MinJ the tangent line only adds to it.
    /// </summary>
    public readonly struct NeoHookeanEnergy : IHyperelasticModel
    {
        /// <summary>Below this J the log is continued linearly (see the type's remarks).</summary>
        public const float MinJ = 0.1f;

        /// <summary>mu, Pa.</summary>
        public readonly float Mu;
        /// <summary>lambda, Pa (&gt; 0).</summary>
        public readonly float Lambda;

        /// <summary>Builds the energy from the (linear) Lame parameters.</summary>
        public NeoHookeanEnergy(in LameParameters lame)
        {
            Mu = lame.Mu;
            Lambda = lame.Lambda;
        }

        /// <summary>For a material: its <see cref="NeoHookeanMaterial.LinearLame"/>.</summary>
        public static NeoHookeanEnergy Of(in NeoHookeanMaterial material) => new NeoHookeanEnergy(material.LinearLame);

        /// <inheritdoc/>
        public float DeviatoricStiffness => Mu;

        /// <inheritdoc/>
        public float HydrostaticStiffness => Lambda;

        /// <summary>ln J, continued by its tangent line below <see cref="MinJ"/>.</summary>
        public static float LogJ(float j) => (float)LogJ((double)j);

        /// <summary>The derivative of <see cref="LogJ(float)"/>.</summary>
        public static float LogJSlope(float j) => j >= MinJ ? 1f / j : 1f / MinJ;

        static readonly double LogMinJ = Math.Log(MinJ);

        static double LogJ(double j) => j >= MinJ ? Math.Log(j) : LogMinJ + (j - MinJ) * (1.0 / MinJ);

        /// <summary>Psi(F), J/m^3; 0 at rest, finite for every finite F.</summary>
        public float EnergyDensity(in Mat3 f)
        {
            double l = LogJ(StableNeoHookeanEnergy.Determinant(f));
            return (float)(0.5 * Mu * Deviatoric(f, l) + 0.5 * Lambda * l * l);
        }

        /// <summary>First Piola-Kirchhoff stress P = mu F + (lambda L - mu) L'(J) cof F (= mu (F - F^-T) + lambda ln J F^-T for J &gt;= MinJ), Pa.</summary>
        public Mat3 FirstPiolaStress(in Mat3 f)
        {
            float j = f.Determinant;
            return f * Mu + DeformationGradient.Cofactor(f) * ((Lambda * LogJ(j) - Mu) * LogJSlope(j));
        }

        /// <inheritdoc/>
        public void Constraints(in Mat3 f, out float cDev, out Mat3 dDev, out float cVol, out Mat3 dVol)
        {
            Mat3 cof = DeformationGradient.Cofactor(f);
            double jj = StableNeoHookeanEnergy.Determinant(f);
            double l = LogJ(jj);
            float slope = LogJSlope((float)jj);
            double d = Deviatoric(f, l);
            if (d > DeformationGradient.RestTolerance)
            {
                // dD/dF = 2 F - 2 L'(J) cof F; dC_D/dF = dD/dF / (2 C_D).
                double c = Math.Sqrt(d);
                float inv = (float)(1.0 / c);
                cDev = (float)c;
                dDev = (f - cof * slope) * inv;
            }
            else
            {
                cDev = 0f;
                dDev = default;
            }
            cVol = (float)l;
            dVol = cof * slope;
        }

        // I_C - 3 - 2 L(J) in double (second order in the strain, each part first order).
        static double Deviatoric(in Mat3 f, double logJ) =>
            Math.Max(0.0, StableNeoHookeanEnergy.FrobeniusSquared(f) - 3.0 - 2.0 * logJ);
    }
}
