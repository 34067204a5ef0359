using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// In-plane Neo-Hookean energy of a thin sheet, on the 3x2 deformation gradient F = [f0 f1]
    /// of a triangle (rest frame in its own plane): I_C = |f0|^2 + |f1|^2, J = |f0 x f1| (the
    /// area ratio, never negative: a sheet can fold but not invert in its plane).
    /// Plane stress gives the sheet's Lame parameters mu_2 = mu, lambda_2 = 2 mu lambda / (lambda + 2 mu)
    /// (= E nu / (1 - nu^2)).
    /// Stable model (Smith et al.'s form in 2D): Psi = mu/2 (I_C - 2) + l/2 ((J - alpha)^2 - (1 - alpha)^2),
    /// alpha = 1 + mu / l, l = lambda_2 + mu (the 3D small-strain expansion carries over, since
    /// det(I + e) = 1 + t + (t^2 - s)/2 also holds in 2D). Classic model:
    /// Psi = mu/2 (I_C - 2) - mu L(J) + lambda_2/2 L(J)^2 with <see cref="NeoHookeanEnergy.LogJ(float)"/>.
    /// As constraints that vanish at rest (see <see cref="StableNeoHookeanEnergy"/> for why):
    /// stable C_D = sqrt(I_C - 2 J) = |s1 - s2| (weight mu), C_H = J - 1 (weight l);
    /// classic C_D = sqrt(I_C - 2 - 2 L(J)) (weight mu), C_H = L(J) (weight lambda_2);
    /// both C_D^2 are non-negative because I_C &gt;= 2 J.
    /// </summary>
    public readonly struct MembraneEnergy
    {
        /// <summary>mu of the energy, Pa.</summary>
        public readonly float Mu;
        /// <summary>The weight of the area constraint, Pa (l for the stable model, lambda_2 for the classic one).</summary>
        public readonly float Lambda;
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
        }

        /// <summary>Psi(F), J/m^3 (per unit rest volume of the sheet), 0 at rest.</summary>
        public float EnergyDensity(Vector3 f0, Vector3 f1)
        {
            Invariants(f0, f1, out double ic, out double j);
            double h = Classic ? LogJ(j) : j - 1.0;
            return (float)(0.5 * Mu * Deviatoric(ic, j) + 0.5 * Lambda * h * h);
        }

        /// <summary>Both constraints and their derivatives with respect to the columns f0, f1.</summary>
        public void Constraints(Vector3 f0, Vector3 f1, out float cDev, out Vector3 dDev0, out Vector3 dDev1,
            out float cVol, out Vector3 dVol0, out Vector3 dVol1)
        {
            Invariants(f0, f1, out double ic, out double j);
            Vector3 c = Vector3.Cross(f0, f1);
            float jf = (float)j;
            // dJ/df0 = f1 x n and dJ/df1 = n x f0 with n = c / |c|; no direction when the triangle is flat.
            Vector3 n = jf > 1e-8f ? c / jf : Vector3.Zero;
            Vector3 j0 = Vector3.Cross(f1, n), j1 = Vector3.Cross(n, f0);
            float slope = Classic ? NeoHookeanEnergy.LogJSlope(jf) : 1f;
            dVol0 = j0 * slope;
            dVol1 = j1 * slope;
            cVol = (float)(Classic ? LogJ(j) : j - 1.0);
            double d = Deviatoric(ic, j);
            if (d > DeformationGradient.RestTolerance)
            {
                // dD/df = 2 f - 2 (dC_H/df) for both models; dC_D/df = dD/df / (2 C_D).
                float inv = (float)(1.0 / Math.Sqrt(d));
                cDev = (float)Math.Sqrt(d);
                dDev0 = (f0 - dVol0) * inv;
                dDev1 = (f1 - dVol1) * inv;
            }
            else
            {
                cDev = 0f;
                dDev0 = dDev1 = Vector3.Zero;
            }
        }

        double Deviatoric(double ic, double j) => Math.Max(0.0, Classic ? ic - 2.0 - 2.0 * LogJ(j) : ic - 2.0 * j);

        static double LogJ(double j) => j >= NeoHookeanEnergy.MinJ ? Math.Log(j) : Math.Log(NeoHookeanEnergy.MinJ) + (j - NeoHookeanEnergy.MinJ) / NeoHookeanEnergy.MinJ;

        // In double: C_D^2 is second order in the strain while its terms are first order.
        static void Invariants(Vector3 f0, Vector3 f1, out double ic, out double j)
        {
            double ax = f0.X, ay = f0.Y, az = f0.Z, bx = f1.X, by = f1.Y, bz = f1.Z;
            ic = ax * ax + ay * ay + az * az + bx * bx + by * by + bz * bz;
            double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
            j = Math.Sqrt(cx * cx + cy * cy + cz * cz);
        }
    }
}
