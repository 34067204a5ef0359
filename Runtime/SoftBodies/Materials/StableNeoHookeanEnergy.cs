using System;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Stable Neo-Hookean energy (Smith, de Goes, Kim 2018, "Stable Neo-Hookean Flesh
    /// Simulation", with its rest-stability shift):
    /// Psi = mu/2 (I_C - 3) + lambda/2 (J - alpha)^2 - mu/2 ln((I_C + 1) / 4) - lambda/2 (1 - alpha)^2,
    /// alpha = 1 + 3 mu / (4 lambda), zero at rest, with mu and lambda from
    /// <see cref="LameParameters.ForStableNeoHookean"/>. It uses J, never ln J, so it is smooth
    /// through J = 0 and pushes an inverted element back out.
    /// <para>
    /// As XPBD constraints. Macklin and Mueller 2021 split this energy (without the log term)
    /// into C_D = sqrt(I_C) and C_H = J - alpha. Both are non-zero at rest, and XPBD's
    /// Gauss-Newton step on a stiff material then drives C_D towards 0, i.e. collapses the
    /// element (measured: a cube with E = 1e9 Pa at 60 Hz fell to 17% of its volume). Here the
    /// same energy is split into two constraints that both vanish at rest:
    /// with j = J - 1, a = I_C - 3 and alpha - 1 = 3 mu / (4 lambda),
    /// Psi = mu/2 D + (lambda - beta mu)/2 j^2, D = a - ln(1 + a/4) - 3/2 j + beta j^2,
    /// so C_D = sqrt(D) (weight mu) and C_H = J - 1 (weight lambda - beta mu). D is zero
    /// exactly on rotations and non-negative for every F (signed J included) when
    /// beta &gt;= 0.15 (near rest D = 3/2 e:e + (beta - 1/8) t^2 for a small strain e, t = tr e;
    /// a numerical search over signed singular values confirms the global bound). beta = 1/4
    /// keeps lambda - beta mu &gt; 0 for every nu &gt; -1/2; below that beta shrinks to keep the
    /// volume weight positive and D is clamped at 0 where it would dip below.
    /// </para>
    /// </summary>
    public readonly struct StableNeoHookeanEnergy : IHyperelasticModel
    {
        /// <summary>mu of the energy, Pa.</summary>
        public readonly float Mu;
        /// <summary>lambda of the energy, Pa.</summary>
        public readonly float Lambda;
        /// <summary>The rest-stability shift alpha = 1 + 3 mu / (4 lambda): dPsi/dF = 0 at F = I.</summary>
        public readonly float Alpha;
        /// <summary>How much volume stiffness the deviatoric constraint borrows (see the type's remarks).</summary>
        public readonly float Beta;

        /// <summary>Builds the energy from its own Lame parameters (already mapped, see <see cref="NeoHookeanMaterial.EnergyLame"/>).</summary>
        public StableNeoHookeanEnergy(in LameParameters energyLame)
        {
            Mu = energyLame.Mu;
            Lambda = energyLame.Lambda;
            Alpha = 1f + 0.75f * Mu / Lambda;
            Beta = MathF.Min(0.25f, 0.5f * Lambda / Mu);
        }

        /// <summary>For a material: its <see cref="NeoHookeanMaterial.EnergyLame"/>.</summary>
        public static StableNeoHookeanEnergy Of(in NeoHookeanMaterial material) =>
            new StableNeoHookeanEnergy(LameParameters.ForStableNeoHookean(material.LinearLame));

        /// <inheritdoc/>
        public float DeviatoricStiffness => Mu;

        /// <inheritdoc/>
        public float HydrostaticStiffness => Lambda - Beta * Mu;

        /// <summary>Psi(F), J/m^3; 0 at rest, finite for every finite F.</summary>
        public float EnergyDensity(in Mat3 f)
        {
            double j = Determinant(f) - 1.0;
            return (float)(0.5 * Mu * Deviatoric(f, j) + 0.5 * HydrostaticStiffness * j * j);
        }

        /// <summary>First Piola-Kirchhoff stress P = mu (1 - 1/(I_C + 1)) F + lambda (J - alpha) cof F, Pa.</summary>
        public Mat3 FirstPiolaStress(in Mat3 f)
        {
            float ic = f.FrobeniusSquared;
            return f * (Mu * ic / (1f + ic)) + DeformationGradient.Cofactor(f) * (Lambda * (f.Determinant - Alpha));
        }

        /// <inheritdoc/>
        public void Constraints(in Mat3 f, out float cDev, out Mat3 dDev, out float cVol, out Mat3 dVol)
        {
            Mat3 cof = DeformationGradient.Cofactor(f);
            // dD/dF = 2 I_C/(I_C + 1) F + (2 beta j - 3/2) cof F, and dC_D/dF = dD/dF / (2 C_D);
            // at rest the constraint has a cone point and no direction, and exerts nothing.
            dDev = StableDeviatoric.Evaluate(f, Beta, out cDev, out float s, out float t, out float j) ? f * s + cof * t : default;
            cVol = j;
            dVol = cof;
        }

        // D = a - ln(1 + a/4) - 3/2 j + beta j^2 for the energy, summed as written in double (each
        // term is first order in the strain and D second order); the constraints take it in float
        // without the cancellation (StableDeviatoric).
        double Deviatoric(in Mat3 f, double j)
        {
            double a = IC(f) - 3.0;
            return Math.Max(0.0, a - Math.Log(1.0 + 0.25 * a) - 1.5 * j + Beta * j * j);
        }

        static double IC(in Mat3 f) =>
            (double)f.C0.X * f.C0.X + (double)f.C0.Y * f.C0.Y + (double)f.C0.Z * f.C0.Z
            + (double)f.C1.X * f.C1.X + (double)f.C1.Y * f.C1.Y + (double)f.C1.Z * f.C1.Z
            + (double)f.C2.X * f.C2.X + (double)f.C2.Y * f.C2.Y + (double)f.C2.Z * f.C2.Z;

        internal static double Determinant(in Mat3 f) =>
            f.C0.X * ((double)f.C1.Y * f.C2.Z - (double)f.C2.Y * f.C1.Z)
            - f.C1.X * ((double)f.C0.Y * f.C2.Z - (double)f.C2.Y * f.C0.Z)
            + f.C2.X * ((double)f.C0.Y * f.C1.Z - (double)f.C1.Y * f.C0.Z);

        internal static double FrobeniusSquared(in Mat3 f) => IC(f);
    }
}
