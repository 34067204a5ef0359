using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The band matrix: reverse Cuthill-McKee numbering, band Cholesky with a diagonal shift where
    /// a pivot is not positive, and the solves.
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
        // Band Cholesky in place (lower triangle); on a non-positive pivot the diagonal is shifted
        // (Levenberg: 1e-10 of the largest diagonal, x4 per retry, at most MaxShifts times) and
        // the factorisation restarts (Step then assembles again with definite element tangents
        // and factors that; _shifted says whether a shift was needed). False when the matrix has no finite positive diagonal or
        // is still not factored after the last shift (a non-finite entry): the step is skipped.
        // Before, the retries were unbounded, and a matrix with a NaN (or a zero diagonal, which
        // made every shift zero) hung the step for good (soft fuzz seed 3: a Newton beam at
        // E 1e9 Pa, nu 0.4999).
        bool Factor()
        {
            _shifted = false;
            Array.Copy(_matrix, _saved, _matrix.Length);
            double largest = 0;
            for (int i = 0; i < _dofs; i++) largest = Math.Max(largest, At(i, i));
            if (!(largest > 0) || double.IsInfinity(largest)) return false;
            double shift = 0;
            for (int tries = 0; !TryFactor(); tries++)
            {
                if (tries == MaxShifts) return false;
                shift = shift == 0 ? 1e-10 * largest : 4 * shift;
                _shifted = true;
                Array.Copy(_saved, _matrix, _matrix.Length);
                for (int i = 0; i < _dofs; i++) At(i, i) += shift;
            }
            return true;
        }

        // 1e-10 x 4^30 is 1e8 times the largest diagonal: the step is then a gradient step of
        // that length scale, and a matrix that still fails has a non-finite entry.
        const int MaxShifts = 30;

        bool TryFactor()
        {
            for (int k = 0; k < _dofs; k++)
            {
                int first = Math.Max(0, k - _band);
                double d = At(k, k);
                for (int s = first; s < k; s++) d -= At(k, s) * At(k, s);
                if (!(d > 0)) return false;
                d = Math.Sqrt(d);
                At(k, k) = d;
                int last = Math.Min(_dofs - 1, k + _band);
                for (int i = k + 1; i <= last; i++)
                {
                    double value = At(i, k);
                    for (int s = Math.Max(first, i - _band); s < k; s++) value -= At(i, s) * At(k, s);
                    At(i, k) = value / d;
                }
            }
            return true;
        }

        // Solves L L^T z = v in place for the vector v[offset .. offset + dofs).
        void Solve(double[] v, int offset)
        {
            for (int i = 0; i < _dofs; i++)
            {
                double value = v[offset + i];
                for (int s = Math.Max(0, i - _band); s < i; s++) value -= At(i, s) * v[offset + s];
                v[offset + i] = value / At(i, i);
            }
            for (int i = _dofs - 1; i >= 0; i--)
            {
                double value = v[offset + i];
                for (int s = i + 1; s <= Math.Min(_dofs - 1, i + _band); s++) value -= At(s, i) * v[offset + s];
                v[offset + i] = value / At(i, i);
            }
        }

        /// <summary>
        /// Reverse Cuthill-McKee numbering of the vertex graph (vertices sharing a tet are
        /// neighbours): breadth-first from a low-degree vertex, neighbours by increasing degree,
        /// reversed. It keeps the band of a mesh to about its smallest cross-section.
        /// </summary>
        static int[] ReverseCuthillMcKee(TetElement[] tets, int n)
        {
            var degree = new int[n];
            foreach (TetElement t in tets) { degree[t.A] += 3; degree[t.B] += 3; degree[t.C] += 3; degree[t.D] += 3; }
            var start = new int[n + 1];
            for (int i = 0; i < n; i++) start[i + 1] = start[i] + degree[i];
            var neighbours = new int[start[n]];
            var fill = new int[n];
            foreach (TetElement t in tets)
            {
                int[] q = { t.A, t.B, t.C, t.D };
                foreach (int a in q)
                    foreach (int b in q)
                        if (a != b) neighbours[start[a] + fill[a]++] = b;
            }
            var sequence = new int[n];
            var seen = new bool[n];
            int count = 0;
            while (count < n)
            {
                int root = -1;
                for (int i = 0; i < n; i++)
                    if (!seen[i] && (root < 0 || degree[i] < degree[root])) root = i;
                seen[root] = true;
                sequence[count++] = root;
                for (int head = count - 1; head < count; head++)
                {
                    int u = sequence[head];
                    int from = count;
                    for (int k = start[u]; k < start[u + 1]; k++)
                    {
                        int nb = neighbours[k];
                        if (seen[nb]) continue;
                        seen[nb] = true;
                        sequence[count++] = nb;
                    }
                    Array.Sort(sequence, from, count - from, new DegreeOrder(degree));
                }
            }
            var order = new int[n];
            for (int k = 0; k < n; k++) order[sequence[k]] = n - 1 - k;
            return order;
        }

        sealed class DegreeOrder : System.Collections.Generic.IComparer<int>
        {
            readonly int[] _degree;
            public DegreeOrder(int[] degree) => _degree = degree;
            public int Compare(int a, int b) => _degree[a] != _degree[b] ? _degree[a].CompareTo(_degree[b]) : a.CompareTo(b);
        }
    }
}
