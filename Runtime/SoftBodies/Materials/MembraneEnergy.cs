using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// In-plane Neo-Hookean energy of a thin sheet, on the 3x2 deformation gradient F = [f0 f1]
    /// of a triangle (rest frame in its own plane): I_C = |f0|^2 + |f1|^2, J = |f0 x f1| (the
    /// area ratio, never negative: a sheet can fold but not invert in its plane).
    /// Plane stress gives the sheet's Lame parameters mu_2 = mu, lambda_2 = 2 mu lambda / (lambda + 2 mu)
    /// (= E nu / (1 - nu^2)). Stable model: Psi = mu/2 (I_C - 2) + l/2 (J - alpha)^2 - const with
    /// alpha = 1 + mu / l and l = lambda_2 + mu (the same small-strain expansion as in 3D, where
    /// det(I + e) = 1 + t + (t^2 - s)/2 also holds); classic model: Psi = mu/2 (I_C - 2) - mu L(J) + lambda_2/2 L(J)^2.
    /// Constraints: C_D = sqrt(I_C) and C_H = J - alpha (stable) or L(J) - mu/lambda_2 (classic).
    /// </summary>
    public readonly struct MembraneEnergy
    {
        /// <summary>mu of the energy, Pa.</summary>
        public readonly float Mu;
        /// <summary>lambda of the energy (after the plane-stress and, for the stable model, rest-stability mapping), Pa.</summary>
        public readonly float Lambda;
        /// <summary>The rest shift of the stable model's area term (0 for the classic model).</summary>
        public readonly float Alpha;
        /// <summary>True for the classic (log) model.</summary>
        public readonly bool Classic;

        /// <summary>The membrane energy of a material.</summary>
        public MembraneEnergy(in NeoHookeanMaterial material)
        {
            LameParameters linear = material.LinearLame;
            float mu = linear.Mu;
            float lambda2 = (float)(2.0 * mu * linear.Lambda / ((double)linear.Lambda + 2.0 * mu));
            Mu = mu;
            Classic = material.Model == MaterialModel.NeoHookean;
            Lambda = Classic ? lambda2 : lambda2 + mu;
            Alpha = Classic ? 0f : 1f + mu / Lambda;
        }

        /// <summary>Psi(F), J/m^3 (per unit rest volume of the sheet), 0 at rest.</summary>
        public float EnergyDensity(Vector3 f0, Vector3 f1)
        {
            float ic = f0.LengthSquared() + f1.LengthSquared();
            float j = Vector3.Cross(f0, f1).Length();
            if (Classic)
            {
                float l = NeoHookeanEnergy.LogJ(j);
                return 0.5f * Mu * (ic - 2f) - Mu * l + 0.5f * Lambda * l * l;
            }
            return 0.5f * Mu * (ic - 2f) + 0.5f * Lambda * (j - 1f) * (j + 1f - 2f * Alpha);
        }

        /// <summary>Both constraints and their derivatives with respect to the columns f0, f1.</summary>
        public void Constraints(Vector3 f0, Vector3 f1, out float cDev, out Vector3 dDev0, out Vector3 dDev1,
            out float cVol, out Vector3 dVol0, out Vector3 dVol1)
        {
            cDev = MathF.Sqrt(f0.LengthSquared() + f1.LengthSquared());
            float inv = cDev > 1e-6f ? 1f / cDev : 0f;
            dDev0 = f0 * inv;
            dDev1 = f1 * inv;
            Vector3 c = Vector3.Cross(f0, f1);
            float j = c.Length();
            // dJ/df0 = f1 x n and dJ/df1 = n x f0 with n = c / |c|; no direction when the triangle is flat.
            Vector3 n = j > 1e-8f ? c / j : Vector3.Zero;
            dVol0 = Vector3.Cross(f1, n);
            dVol1 = Vector3.Cross(n, f0);
            if (Classic)
            {
                float slope = NeoHookeanEnergy.LogJSlope(j);
                cVol = NeoHookeanEnergy.LogJ(j) - Mu / Lambda;
                dVol0 *= slope;
                dVol1 *= slope;
            }
            else
            {
                cVol = j - Alpha;
            }
        }
    }
}
