using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The size of the Green–Lagrange strain of every element of a soft body against its mesh's
    /// rest shape, for the viewer's strain colours. J (the volume ratio) alone hides the strain
    /// of nearly incompressible material: a jelly at ν = 0.48 squashed by 10 % keeps J within
    /// 1 % of 1.
    /// <para>
    /// With rest edge vectors D0 (columns, from the element's first vertex) and current edges D,
    /// E = D0^-T (DᵀD − D0ᵀD0) D0^-1 / 2 in an orthonormal rest frame. M = G0^-1 (G − G0) / 2 with
    /// the Gram matrices G0 = D0ᵀD0 and G = DᵀD equals D0^-1 E D0, a similar matrix, so
    /// ‖E‖_F = sqrt(tr(M²)) without building a rest frame. The same formula serves tetrahedra
    /// (3 edges, 3×3) and shell triangles (2 edges, 2×2).
    /// </para>
    /// Plastic flow moves the rest shape; this measures against the original mesh.
    /// </summary>
    internal sealed class ElementStrain
    {
        readonly int[] _elements;
        readonly int _per;            // vertices per element: 4 or 3
        readonly float[] _restGram;   // per element: G0, row-major 3x3 (a triangle uses the top-left 2x2)
        readonly float[] _restInverse; // per element: G0^-1, same layout

        /// <summary>Precomputes the rest Gram matrices of <paramref name="mesh"/>'s elements.</summary>
        public ElementStrain(SoftMesh mesh)
        {
            _per = mesh.IsShell ? 3 : 4;
            _elements = (mesh.IsShell ? mesh.Triangles : mesh.Tetrahedra).ToArray();
            int count = _elements.Length / _per;
            _restGram = new float[9 * count];
            _restInverse = new float[9 * count];
            ReadOnlySpan<Vector3> rest = mesh.Vertices;
            Span<Vector3> edges = stackalloc Vector3[3];
            for (int e = 0; e < count; e++)
            {
                Edges(rest, e, edges);
                Span<float> g = _restGram.AsSpan(9 * e, 9), inv = _restInverse.AsSpan(9 * e, 9);
                Gram(edges, g);
                Invert(g, inv);
            }
        }

        /// <summary>Writes ‖E‖_F of every element (0 at rest) for the current <paramref name="positions"/>.</summary>
        public void Compute(ReadOnlySpan<Vector3> positions, Span<float> into)
        {
            int n = _per - 1;
            Span<Vector3> edges = stackalloc Vector3[3];
            Span<float> g = stackalloc float[9];
            Span<float> m = stackalloc float[9];
            for (int e = 0; e < into.Length; e++)
            {
                Edges(positions, e, edges);
                Gram(edges, g);
                ReadOnlySpan<float> g0 = _restGram.AsSpan(9 * e, 9), inv = _restInverse.AsSpan(9 * e, 9);
                // M = G0^-1 (G - G0) / 2
                for (int i = 0; i < n; i++)
                    for (int j = 0; j < n; j++)
                    {
                        float s = 0;
                        for (int k = 0; k < n; k++) s += inv[3 * i + k] * (g[3 * k + j] - g0[3 * k + j]);
                        m[3 * i + j] = 0.5f * s;
                    }
                float trace = 0;
                for (int i = 0; i < n; i++)
                    for (int j = 0; j < n; j++) trace += m[3 * i + j] * m[3 * j + i];
                into[e] = MathF.Sqrt(MathF.Max(0, trace));
            }
        }

        void Edges(ReadOnlySpan<Vector3> x, int element, Span<Vector3> edges)
        {
            int o = _per * element;
            Vector3 origin = x[_elements[o]];
            for (int k = 1; k < _per; k++) edges[k - 1] = x[_elements[o + k]] - origin;
        }

        void Gram(ReadOnlySpan<Vector3> edges, Span<float> g)
        {
            int n = _per - 1;
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) g[3 * i + j] = Vector3.Dot(edges[i], edges[j]);
        }

        void Invert(ReadOnlySpan<float> g, Span<float> inv)
        {
            if (_per == 3)
            {
                float det = g[0] * g[4] - g[1] * g[3];
                float r = det != 0 ? 1 / det : 0;   // a degenerate rest element reports 0 strain
                inv[0] = g[4] * r; inv[1] = -g[1] * r; inv[3] = -g[3] * r; inv[4] = g[0] * r;
                return;
            }
            float c00 = g[4] * g[8] - g[5] * g[7], c01 = g[5] * g[6] - g[3] * g[8], c02 = g[3] * g[7] - g[4] * g[6];
            float d = g[0] * c00 + g[1] * c01 + g[2] * c02;
            float s = d != 0 ? 1 / d : 0;
            inv[0] = c00 * s; inv[1] = (g[2] * g[7] - g[1] * g[8]) * s; inv[2] = (g[1] * g[5] - g[2] * g[4]) * s;
            inv[3] = c01 * s; inv[4] = (g[0] * g[8] - g[2] * g[6]) * s; inv[5] = (g[2] * g[3] - g[0] * g[5]) * s;
            inv[6] = c02 * s; inv[7] = (g[1] * g[6] - g[0] * g[7]) * s; inv[8] = (g[0] * g[4] - g[1] * g[3]) * s;
        }
    }
}
