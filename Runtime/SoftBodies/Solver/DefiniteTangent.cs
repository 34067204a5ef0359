using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Makes an element's tangent dP/dF (9 x 9, symmetric) positive definite for the Newton
    /// step: each eigenvalue is replaced by its absolute value (the absolute eigenvalue filter
    /// of Chen, Liu, Levin, Zheng and Jacobson 2024, "Stabler Neo-Hookean Simulation: Absolute
    /// Eigenvalue Filtering for Projected Newton"; projected Newton, Teran, Sifakis, Irving and
    /// Fedkiw 2005, sets them to zero). The element Hessian is B^T C B with B the rest shape's
    /// linear map, so it is then positive semi-definite too.
    /// <para>
    /// Why: both Neo-Hookean tangents hold a term lambda (J - alpha) d^2J/dF^2 (for the classic
    /// model (lambda ln J - mu) d(F^-T)/dF), whose eigenvalues are plus and minus that factor
    /// times F's singular values. For a nearly incompressible material lambda is thousands of
    /// times mu, so a compression of a percent makes the tangent indefinite far beyond what the
    /// vertices' inertia holds; the band factor then got through only with a diagonal shift
    /// just large enough, the system was left nearly singular, and the step along those
    /// directions came out metres long (a nu = 0.4999 sphere pinned to a body and landing at
    /// 1.1 m/s: steps of 2 m, scaled to a quarter edge by the trust region; it stored 270 J of
    /// strain from a 4 J landing and threw the body about). Zeroing the negative eigenvalues
    /// instead of flipping them left a box of E 7.9e9 Pa at nu 0.4999 free to crush along them
    /// (soft fuzz seed 86: 2e9 J of strain).
    /// </para>
    /// Used only when the exact system is not positive definite (see
    /// <see cref="ImplicitNewtonSolver"/>): where the inertia holds the exact tangent, the exact
    /// Newton step lands closer to the substep's minimum (a nu = 0.3 cube thrown at the ground
    /// at 10 m/s, whose system never needs it, kept min J 0.79 with the exact tangent and 0.35
    /// with every element filtered). An element whose tangent is already positive definite
    /// (a Cholesky factor of it succeeds) is left bit for bit as it was.
    /// </summary>
    internal static class DefiniteTangent
    {
        /// <summary>Filters <paramref name="c"/> (row-major 9 x 9) in place; true when it changed.</summary>
        public static bool Project(Span<double> c)
        {
            Span<double> a = stackalloc double[81];
            for (int i = 0; i < 9; i++)
                for (int j = 0; j < 9; j++)
                    a[9 * i + j] = 0.5 * (c[9 * i + j] + c[9 * j + i]);
            if (IsPositiveDefinite(a)) return false;

            // Cyclic Jacobi: a -> diag(eigenvalues), v the eigenvectors (columns).
            Span<double> v = stackalloc double[81];
            v.Clear();
            for (int i = 0; i < 9; i++) v[10 * i] = 1;
            double scale = 0;
            for (int k = 0; k < 81; k++) scale += a[k] * a[k];
            if (!(scale > 0) || double.IsInfinity(scale)) return false;
            for (int sweep = 0; sweep < 30; sweep++)
            {
                double off = 0;
                for (int p = 0; p < 9; p++)
                    for (int q = p + 1; q < 9; q++) off += a[9 * p + q] * a[9 * p + q];
                if (off <= 1e-24 * scale) break;
                for (int p = 0; p < 9; p++)
                    for (int q = p + 1; q < 9; q++)
                    {
                        double apq = a[9 * p + q];
                        if (apq == 0) continue;
                        // The rotation that zeroes a_pq (Golub and Van Loan, Algorithm 8.5.1).
                        double theta = (a[9 * q + q] - a[9 * p + p]) / (2 * apq);
                        double t = Math.Sign(theta) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1));
                        if (theta == 0) t = 1;
                        double cs = 1 / Math.Sqrt(t * t + 1), sn = t * cs;
                        for (int k = 0; k < 9; k++)
                        {
                            double akp = a[9 * k + p], akq = a[9 * k + q];
                            a[9 * k + p] = cs * akp - sn * akq;
                            a[9 * k + q] = sn * akp + cs * akq;
                        }
                        for (int k = 0; k < 9; k++)
                        {
                            double apk = a[9 * p + k], aqk = a[9 * q + k];
                            a[9 * p + k] = cs * apk - sn * aqk;
                            a[9 * q + k] = sn * apk + cs * aqk;
                        }
                        for (int k = 0; k < 9; k++)
                        {
                            double vkp = v[9 * k + p], vkq = v[9 * k + q];
                            v[9 * k + p] = cs * vkp - sn * vkq;
                            v[9 * k + q] = sn * vkp + cs * vkq;
                        }
                    }
            }
            // c = V |diag| V^T
            for (int i = 0; i < 9; i++)
                for (int j = 0; j < 9; j++)
                {
                    double s = 0;
                    for (int k = 0; k < 9; k++)
                    {
                        double e = Math.Abs(a[10 * k]);
                        s += v[9 * i + k] * e * v[9 * j + k];
                    }
                    c[9 * i + j] = s;
                }
            return true;
        }

        // Whether a Cholesky factor of the symmetric 9 x 9 a exists (a is left unchanged).
        static bool IsPositiveDefinite(ReadOnlySpan<double> a)
        {
            Span<double> l = stackalloc double[81];
            for (int k = 0; k < 9; k++)
            {
                double d = a[9 * k + k];
                for (int s = 0; s < k; s++) d -= l[9 * k + s] * l[9 * k + s];
                if (!(d > 0)) return false;
                d = Math.Sqrt(d);
                l[9 * k + k] = d;
                for (int i = k + 1; i < 9; i++)
                {
                    double value = a[9 * i + k];
                    for (int s = 0; s < k; s++) value -= l[9 * i + s] * l[9 * k + s];
                    l[9 * i + k] = value / d;
                }
            }
            return true;
        }
    }
}
