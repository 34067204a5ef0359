using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Cholesky factorisation of a small dense symmetric matrix, row-major n x n, in place
    /// (L in the lower triangle), and the solve with it. Used by the static-equilibrium
    /// reference, the Newton solver's Schur complement on attached bodies, and the block
    /// projection of a body's attachments (on the stack: spans).
    /// </summary>
    internal static class DenseCholesky
    {
        /// <summary>Factors <paramref name="a"/> = L L^T in place; false on a non-positive pivot (not positive definite).</summary>
        public static bool Factor(Span<double> a, int n)
        {
            for (int k = 0; k < n; k++)
            {
                double d = a[k * n + k];
                for (int s = 0; s < k; s++) d -= a[k * n + s] * a[k * n + s];
                if (!(d > 0)) return false;
                d = Math.Sqrt(d);
                a[k * n + k] = d;
                for (int i = k + 1; i < n; i++)
                {
                    double v = a[i * n + k];
                    for (int s = 0; s < k; s++) v -= a[i * n + s] * a[k * n + s];
                    a[i * n + k] = v / d;
                }
            }
            return true;
        }

        /// <summary>Solves L L^T x = <paramref name="b"/> in place with the factor <paramref name="l"/> from <see cref="Factor"/>.</summary>
        public static void Solve(ReadOnlySpan<double> l, int n, Span<double> b)
        {
            for (int i = 0; i < n; i++)
            {
                double v = b[i];
                for (int s = 0; s < i; s++) v -= l[i * n + s] * b[s];
                b[i] = v / l[i * n + i];
            }
            for (int i = n - 1; i >= 0; i--)
            {
                double v = b[i];
                for (int s = i + 1; s < n; s++) v -= l[s * n + i] * b[s];
                b[i] = v / l[i * n + i];
            }
        }
    }
}
