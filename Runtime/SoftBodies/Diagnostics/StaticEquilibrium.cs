using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The static equilibrium of a soft body on its own mesh: Newton's method with a backtracking
    /// (Armijo) line search on the total potential E(x) = sum_tets V Psi(F) - f . x, with fixed
    /// degrees of freedom as Dirichlet conditions and lumped gravity or point loads as f.
    /// It is the reference that "error" is measured against (the converged answer of the same
    /// discretisation), not a runtime solver: the Hessian is dense and factored by Cholesky in
    /// double, so it is meant for meshes of up to a few hundred vertices. Where the exact Hessian
    /// is not positive definite (compressed Stable Neo-Hookean elements, whose cofactor term is
    /// indefinite) a diagonal shift is added until the factorisation succeeds (Levenberg), which
    /// keeps every step a descent direction; the gradient stays exact, so the fixed point is.
    /// </summary>
    public sealed class StaticEquilibrium
    {
        readonly int _n;
        readonly int[] _tets;
        readonly double[] _rest;       // per tet: 12 vertex coefficients r_a[j] (a = 0..3, j = 0..2)
        readonly double[] _volume;
        readonly double[] _force;
        readonly bool[] _fixed;
        readonly double[] _h, _g, _d, _trial, _c, _p;
        readonly NeoHookeanTangent _tangent;

        /// <summary>Current positions, 3 per vertex (x, y, z); starts at the rest shape.</summary>
        public double[] X { get; }

        /// <summary>Lumped vertex masses, kg (density times a quarter of each adjacent tet's volume).</summary>
        public double[] Mass { get; }

        /// <summary>Newton iterations taken by the last <see cref="Solve"/>.</summary>
        public int Iterations { get; private set; }

        /// <summary>Largest free-DOF residual force after the last <see cref="Solve"/>, N.</summary>
        public double Residual { get; private set; }

        /// <summary>Builds the problem for a tet mesh and material, unloaded and unconstrained, at rest.</summary>
        public StaticEquilibrium(SoftMesh mesh, in NeoHookeanMaterial material)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (mesh.IsShell) throw new ArgumentException("StaticEquilibrium needs a tetrahedral mesh, got a shell.", nameof(mesh));
            material.Validate();
            _n = mesh.VertexCount;
            _tets = mesh.Tetrahedra.ToArray();
            int tets = _tets.Length / 4;
            X = new double[3 * _n];
            Mass = new double[_n];
            ReadOnlySpan<Vector3> v = mesh.Vertices;
            for (int i = 0; i < _n; i++) { X[3 * i] = v[i].X; X[3 * i + 1] = v[i].Y; X[3 * i + 2] = v[i].Z; }
            _rest = new double[12 * tets];
            _volume = new double[tets];
            for (int t = 0; t < tets; t++)
            {
                var dm = new double[9];
                for (int k = 0; k < 3; k++)
                    for (int i = 0; i < 3; i++) dm[3 * i + k] = X[3 * _tets[4 * t + k + 1] + i] - X[3 * _tets[4 * t] + i];
                double det = NeoHookeanTangent.Det(dm);
                if (!(det > 0)) throw new ArgumentException($"tet {t} has non-positive rest volume.", nameof(mesh));
                var inv = new double[9];
                Inverse(dm, det, inv);
                _volume[t] = det / 6.0;
                for (int j = 0; j < 3; j++)
                {
                    double sum = 0;
                    for (int k = 0; k < 3; k++) { _rest[12 * t + 3 * (k + 1) + j] = inv[3 * k + j]; sum += inv[3 * k + j]; }
                    _rest[12 * t + j] = -sum;
                }
                for (int a = 0; a < 4; a++) Mass[_tets[4 * t + a]] += material.Density * _volume[t] / 4.0;
            }
            _tangent = new NeoHookeanTangent(material);
            _force = new double[3 * _n];
            _fixed = new bool[3 * _n];
            _h = new double[9 * _n * _n];
            _g = new double[3 * _n];
            _d = new double[3 * _n];
            _trial = new double[3 * _n];
            _c = new double[81];
            _p = new double[9];
        }

        /// <summary>Adds the lumped weight m_i g of every vertex to the load.</summary>
        public void AddGravity(Vector3 gravity)
        {
            for (int i = 0; i < _n; i++)
            {
                _force[3 * i] += Mass[i] * gravity.X; _force[3 * i + 1] += Mass[i] * gravity.Y; _force[3 * i + 2] += Mass[i] * gravity.Z;
            }
        }

        /// <summary>Adds a point force (N) on a vertex.</summary>
        public void AddForce(int vertex, Vector3 force)
        {
            if ((uint)vertex >= (uint)_n) throw new ArgumentOutOfRangeException(nameof(vertex));
            _force[3 * vertex] += force.X; _force[3 * vertex + 1] += force.Y; _force[3 * vertex + 2] += force.Z;
        }

        /// <summary>Fixes one coordinate (axis 0, 1, 2) of a vertex at <paramref name="value"/> (a Dirichlet condition).</summary>
        public void Fix(int vertex, int axis, double value)
        {
            if ((uint)vertex >= (uint)_n) throw new ArgumentOutOfRangeException(nameof(vertex));
            if ((uint)axis > 2) throw new ArgumentOutOfRangeException(nameof(axis));
            if (double.IsNaN(value) || double.IsInfinity(value)) throw new ArgumentException("value must be finite.", nameof(value));
            _fixed[3 * vertex + axis] = true;
            X[3 * vertex + axis] = value;
        }

        /// <summary>Fixes all three coordinates of a vertex where it is now.</summary>
        public void Pin(int vertex)
        {
            for (int a = 0; a < 3; a++) Fix(vertex, a, X[3 * vertex + a]);
        }

        /// <summary>The position of a vertex.</summary>
        public Vector3 Position(int vertex) => new Vector3((float)X[3 * vertex], (float)X[3 * vertex + 1], (float)X[3 * vertex + 2]);

        /// <summary>Total potential energy at the current positions, J.</summary>
        public double Energy() => Energy(X);

        /// <summary>
        /// Runs Newton until the largest free residual force is below <paramref name="tolerance"/>
        /// times the larger of the largest load and the first residual, or the Newton step no longer
        /// moves any coordinate by more than 1e-12 of the mesh's extent (round-off reached), or
        /// <paramref name="maxIterations"/>. Returns true when converged.
        /// </summary>
        public bool Solve(int maxIterations = 100, double tolerance = 1e-9)
        {
            double fmax = 0;
            for (int i = 0; i < _force.Length; i++) fmax = Math.Max(fmax, Math.Abs(_force[i]));
            double limit = -1, extent = 0;
            int m = 3 * _n;
            for (int i = 0; i < m; i++) extent = Math.Max(extent, Math.Abs(X[i]));
            bool stalled = false;
            for (Iterations = 0; Iterations < maxIterations; Iterations++)
            {
                double e0 = Assemble(X, hessian: true);
                Residual = 0;
                for (int i = 0; i < m; i++) if (!_fixed[i]) Residual = Math.Max(Residual, Math.Abs(_g[i]));
                if (limit < 0) limit = tolerance * Math.Max(fmax, Residual);
                if (Residual <= limit || stalled) return true;
                for (int i = 0; i < m; i++)
                {
                    if (!_fixed[i]) { _d[i] = -_g[i]; continue; }
                    for (int k = 0; k < m; k++) { _h[i * m + k] = 0; _h[k * m + i] = 0; }
                    _h[i * m + i] = 1;
                    _d[i] = 0;
                }
                FactorWithShift(m);
                SolveFactored(m, _d);
                double slope = 0, dmax = 0;
                for (int i = 0; i < m; i++) { slope += _g[i] * _d[i]; dmax = Math.Max(dmax, Math.Abs(_d[i])); }
                stalled = dmax <= 1e-12 * Math.Max(extent, 1e-6);
                double step = 1;
                bool accepted = false;
                for (int k = 0; k < 60; k++, step *= 0.5)
                {
                    for (int i = 0; i < m; i++) _trial[i] = X[i] + step * _d[i];
                    double e = Energy(_trial);
                    if (e <= e0 + 1e-4 * step * slope || Math.Abs(e - e0) <= 1e-14 * Math.Abs(e0)) { accepted = true; break; }
                }
                if (!accepted) break;
                Array.Copy(_trial, X, m);
            }
            Assemble(X, hessian: false);
            Residual = 0;
            for (int i = 0; i < m; i++) if (!_fixed[i]) Residual = Math.Max(Residual, Math.Abs(_g[i]));
            return Residual <= limit || stalled;
        }

        double Energy(double[] x)
        {
            double e = 0;
            var f = new double[9];
            for (int t = 0; t < _volume.Length; t++)
            {
                DeformationGradientOf(x, t, f);
                e += _volume[t] * _tangent.Psi(f);
            }
            for (int i = 0; i < x.Length; i++) e -= _force[i] * x[i];
            return e;
        }

        /// <summary>Gradient into _g and (optionally) the Hessian into _h; returns the energy.</summary>
        double Assemble(double[] x, bool hessian)
        {
            int m = 3 * _n;
            Array.Clear(_g, 0, m);
            if (hessian) Array.Clear(_h, 0, _h.Length);
            double e = 0;
            var f = new double[9];
            for (int t = 0; t < _volume.Length; t++)
            {
                DeformationGradientOf(x, t, f);
                double vol = _volume[t];
                e += vol * _tangent.Psi(f);
                _tangent.Stress(f, _p);
                int r = 12 * t;
                for (int a = 0; a < 4; a++)
                {
                    int va = _tets[4 * t + a];
                    for (int i = 0; i < 3; i++)
                    {
                        double s = 0;
                        for (int j = 0; j < 3; j++) s += _p[3 * i + j] * _rest[r + 3 * a + j];
                        _g[3 * va + i] += vol * s;
                    }
                }
                if (!hessian) continue;
                _tangent.Tangent(f, _c);
                // K[(a,i),(b,l)] = V sum_j sum_q r_a[j] C[(i,j),(l,q)] r_b[q].
                for (int a = 0; a < 4; a++)
                {
                    int va = _tets[4 * t + a];
                    for (int b = 0; b < 4; b++)
                    {
                        int vb = _tets[4 * t + b];
                        for (int i = 0; i < 3; i++)
                            for (int l = 0; l < 3; l++)
                            {
                                double s = 0;
                                for (int j = 0; j < 3; j++)
                                {
                                    double ra = _rest[r + 3 * a + j];
                                    for (int q = 0; q < 3; q++) s += ra * _c[9 * (3 * i + j) + 3 * l + q] * _rest[r + 3 * b + q];
                                }
                                _h[(3 * va + i) * m + 3 * vb + l] += vol * s;
                            }
                    }
                }
            }
            for (int i = 0; i < m; i++)
            {
                e -= _force[i] * x[i];
                _g[i] -= _force[i];
            }
            return e;
        }

        void DeformationGradientOf(double[] x, int t, double[] f)
        {
            int r = 12 * t;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                {
                    double s = 0;
                    for (int a = 0; a < 4; a++) s += x[3 * _tets[4 * t + a] + i] * _rest[r + 3 * a + j];
                    f[3 * i + j] = s;
                }
        }

        void FactorWithShift(int m)
        {
            double maxDiag = 0;
            for (int i = 0; i < m; i++) maxDiag = Math.Max(maxDiag, Math.Abs(_h[i * m + i]));
            var original = (double[])_h.Clone();
            double shift = 0;
            while (!Cholesky(m))
            {
                shift = shift == 0 ? 1e-10 * maxDiag : 4 * shift;
                Array.Copy(original, _h, _h.Length);
                for (int i = 0; i < m; i++) _h[i * m + i] += shift;
            }
        }

        bool Cholesky(int m) => DenseCholesky.Factor(_h, m);

        void SolveFactored(int m, double[] b) => DenseCholesky.Solve(_h, m, b);

        static void Inverse(double[] a, double det, double[] inv)
        {
            Span<double> c = stackalloc double[9];
            NeoHookeanTangent.Cofactor(a, c);
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) inv[3 * i + j] = c[3 * j + i] / det;
        }
    }
}
