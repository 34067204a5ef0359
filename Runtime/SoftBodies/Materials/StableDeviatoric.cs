using System;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The deviatoric constraint of <see cref="StableNeoHookeanEnergy"/>, C_D = sqrt(D) with
    /// D = a - ln(1 + a/4) - 3/2 j + beta j^2 (a = I_C - 3, j = J - 1), evaluated in float
    /// without cancellation. Each term of D is first order in the strain and D is second order,
    /// so summed as written D is lost to rounding near rest; with H = F - I the first-order
    /// parts cancel symbolically instead:
    /// a = 2 tr H + |H|^2, j = tr H + I2(H) + det H (I2: the sum of the principal 2x2 minors),
    /// so 3/4 a - 3/2 j = 3/4 |H|^2 - 3/2 (I2 + det H), and with u = a/4,
    /// a - ln(1 + u) - 3/2 j = [u - ln(1 + u)] + 3/4 |H|^2 - 3/2 (I2 + det H).
    /// u - ln(1 + u) is itself second order: with w = u / (2 + u), ln(1 + u) = 2 atanh w and
    /// u - 2w = u w, so u - ln(1 + u) = w (u - 2 w^2 (1/3 + w^2/5 + w^4/7 + ...)), a series whose
    /// first omitted term is below 2e-9 of the sum for |w| &lt;= <see cref="SeriesLimit"/>
    /// (strains up to about 25 %); beyond it the terms are large and the logarithm is taken directly.
    /// Every operation is written out in one order so that the eight-lane kernel
    /// (XpbdTetSolverWide, .NET only) repeats it lane by lane, bit for bit.
    /// </summary>
    internal static class StableDeviatoric
    {
        /// <summary>Largest |w| = |u / (2 + u)| for which u - ln(1 + u) is summed as a series (u from -1/3 to 1/2).</summary>
        public const float SeriesLimit = 0.2f;

        /// <summary>
        /// C_D = sqrt(D), the factors s and t of dC_D/dF = s F + t cof F
        /// (s = I_C / ((I_C + 1) C_D), t = (2 beta j - 3/2) / (2 C_D)) and j = J - 1; false, with
        /// C_D, s and t zero, where D is within <see cref="DeformationGradient.RestTolerance"/> of 0
        /// (at rest the constraint has a cone point and no direction).
        /// </summary>
        public static bool Evaluate(in Mat3 f, float beta, out float cDev, out float s, out float t, out float j)
        {
            float h00 = f.C0.X - 1f, h10 = f.C0.Y, h20 = f.C0.Z;
            float h01 = f.C1.X, h11 = f.C1.Y - 1f, h21 = f.C1.Z;
            float h02 = f.C2.X, h12 = f.C2.Y, h22 = f.C2.Z - 1f;
            float tr = h00 + h11 + h22;
            float sq = h00 * h00 + h10 * h10 + h20 * h20 + h01 * h01 + h11 * h11 + h21 * h21 + h02 * h02 + h12 * h12 + h22 * h22;
            float minors = h00 * h11 - h01 * h10 + h11 * h22 - h12 * h21 + h00 * h22 - h02 * h20;
            float det = h00 * (h11 * h22 - h12 * h21) - h01 * (h10 * h22 - h12 * h20) + h02 * (h10 * h21 - h11 * h20);
            float higher = minors + det;
            j = tr + higher;
            float a = 2f * tr + sq;
            float u = 0.25f * a;
            float w = u / (2f + u);
            float log = MathF.Abs(w) <= SeriesLimit ? Series(u, w) : Direct(u);
            float d = log + (0.75f * sq - 1.5f * higher) + beta * j * j;
            if (!(d > (float)DeformationGradient.RestTolerance))
            {
                cDev = s = t = 0f;
                return false;
            }
            cDev = MathF.Sqrt(d);
            s = (3f + a) / ((4f + a) * cDev);
            t = (2f * beta * j - 1.5f) / (2f * cDev);
            return true;
        }

        /// <summary>u - ln(1 + u) by the series in w = u / (2 + u) (|w| &lt;= <see cref="SeriesLimit"/>).</summary>
        public static float Series(float u, float w)
        {
            float z = w * w;
            float p = (((z * (1f / 11f) + 1f / 9f) * z + 1f / 7f) * z + 1f / 5f) * z + 1f / 3f;
            return w * (u - 2f * z * p);
        }

        /// <summary>u - ln(1 + u) directly, in double (|w| beyond <see cref="SeriesLimit"/>, where its two terms do not cancel).</summary>
        public static float Direct(float u) => (float)(u - Math.Log(1.0 + u));
    }
}
