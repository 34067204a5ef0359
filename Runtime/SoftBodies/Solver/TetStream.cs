using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The tet solver's data as structure of arrays, in the same (colour) order as
    /// <see cref="SoftBody.Tets"/>: each field is a run of <see cref="Count"/> values, so the
    /// elements e .. e + 7 of one colour are eight consecutive values of every field and a SIMD
    /// kernel reads them with one load per field (XpbdTetSolverWide, .NET only); the scalar
    /// kernels read the same arrays. <see cref="SoftBody.Tets"/> stays the record of the rest
    /// state (diagnostics, plastic flow, the Newton solver and saved states read it) and is
    /// copied in by <see cref="LoadElements"/> whenever it changes.
    /// </summary>
    internal sealed class TetStream
    {
        /// <summary>Gradient fields: D0..D3 (x, y, z each), H0..H3, then KDD, KDH, KHH.</summary>
        public const int GradientFields = 27;

        /// <summary>
        /// Whether the tet passes use the eight-lane kernels (.NET with AVX); otherwise, and for
        /// the last few elements of a colour, the scalar ones, whose results are bit-identical.
        /// Tests switch it off to compare the two.
        /// </summary>
#if NET
        public static bool WideKernels = Lanes8.IsSupported;
#else
        public static bool WideKernels = false;
#endif

        /// <summary>Elements.</summary>
        public readonly int Count;

        /// <summary>Vertex indices: A at [e], B at [n + e], C at [2n + e], D at [3n + e].</summary>
        public readonly int[] Vertices;

        /// <summary>Dm^-1 by columns: component k of column j at [(3 j + k) n + e].</summary>
        public readonly float[] RestInverse;

        /// <summary>Rest volume, m^3.</summary>
        public readonly float[] RestVolume;

        /// <summary>
        /// The gradients the last position iteration kept for the damping pass (the fields of
        /// <see cref="TetGradients"/> in declaration order): field f at [f n + e].
        /// </summary>
        public readonly float[] Gradients;

        /// <summary>
        /// Per vertex (W, FreeW, M, inverted), packed once per step so that a kernel loads a vertex's
        /// three mass values with one 16-byte load (<see cref="Pack"/>). The fourth value is 1
        /// once a tet of the vertex was seen inverted in this step (<see cref="VolumeFloor"/>).
        /// </summary>
        public readonly Vector4[] Masses;

        /// <summary>
        /// Per element, its vertices' masses as runs (packed once per step with <see cref="Masses"/>):
        /// W of A, B, C, D in fields 0-3, M of A, B, C, D in fields 4-7, and in field 8 1 where all
        /// four vertices are free (FreeW &gt; 0; the torque-free projection applies) else 0. The
        /// eight-lane kernels load these instead of gathering four vertices' masses per pass.
        /// </summary>
        public readonly float[] ElementMasses;

        /// <summary>Fields of <see cref="ElementMasses"/>.</summary>
        public const int ElementMassFields = 9;

        /// <summary>
        /// Whether the body may be loaded from outside in this step (a rigid shape it may touch,
        /// an attachment, or a pin): the <see cref="VolumeFloor"/> holds its tets only then.
        /// </summary>
        public bool Loaded;

        public TetStream(int count, int vertices)
        {
            Count = count;
            Vertices = new int[4 * count];
            RestInverse = new float[9 * count];
            RestVolume = new float[count];
            Gradients = new float[GradientFields * count];
            Masses = new Vector4[vertices];
            ElementMasses = new float[ElementMassFields * count];
        }

        /// <summary>Copies indices, rest inverses and volumes from the element records.</summary>
        public void LoadElements(TetElement[] tets)
        {
            int n = Count;
            for (int e = 0; e < n; e++)
            {
                ref TetElement t = ref tets[e];
                Vertices[e] = t.A;
                Vertices[n + e] = t.B;
                Vertices[2 * n + e] = t.C;
                Vertices[3 * n + e] = t.D;
                RestInverse[e] = t.RestInverse.C0.X;
                RestInverse[n + e] = t.RestInverse.C0.Y;
                RestInverse[2 * n + e] = t.RestInverse.C0.Z;
                RestInverse[3 * n + e] = t.RestInverse.C1.X;
                RestInverse[4 * n + e] = t.RestInverse.C1.Y;
                RestInverse[5 * n + e] = t.RestInverse.C1.Z;
                RestInverse[6 * n + e] = t.RestInverse.C2.X;
                RestInverse[7 * n + e] = t.RestInverse.C2.Y;
                RestInverse[8 * n + e] = t.RestInverse.C2.Z;
                RestVolume[e] = t.RestVolume;
            }
        }

        /// <summary>
        /// Packs (W, FreeW, M, 0) per vertex and <see cref="ElementMasses"/> per element; call after
        /// anything changes them, before the substeps.
        /// </summary>
        public void Pack(float[] w, float[] freeW, float[] m)
        {
            for (int i = 0; i < Masses.Length; i++) Masses[i] = new Vector4(w[i], freeW[i], m[i], 0f);
            int n = Count;
            float[] em = ElementMasses;
            for (int e = 0; e < n; e++)
            {
                bool free = true;
                for (int k = 0; k < 4; k++)
                {
                    int v = Vertices[k * n + e];
                    em[k * n + e] = w[v];
                    em[(4 + k) * n + e] = m[v];
                    free &= freeW[v] > 0f;
                }
                em[8 * n + e] = free ? 1f : 0f;
            }
        }

        /// <summary>Writes the kept gradients into element records (for a saved state).</summary>
        public void ExportGradients(TetGradients[] into)
        {
            int n = Count;
            float[] g = Gradients;
            for (int e = 0; e < n; e++)
            {
                into[e] = new TetGradients
                {
                    D0 = new Vector3(g[e], g[n + e], g[2 * n + e]),
                    D1 = new Vector3(g[3 * n + e], g[4 * n + e], g[5 * n + e]),
                    D2 = new Vector3(g[6 * n + e], g[7 * n + e], g[8 * n + e]),
                    D3 = new Vector3(g[9 * n + e], g[10 * n + e], g[11 * n + e]),
                    H0 = new Vector3(g[12 * n + e], g[13 * n + e], g[14 * n + e]),
                    H1 = new Vector3(g[15 * n + e], g[16 * n + e], g[17 * n + e]),
                    H2 = new Vector3(g[18 * n + e], g[19 * n + e], g[20 * n + e]),
                    H3 = new Vector3(g[21 * n + e], g[22 * n + e], g[23 * n + e]),
                    KDD = g[24 * n + e],
                    KDH = g[25 * n + e],
                    KHH = g[26 * n + e],
                };
            }
        }

        /// <summary>Reads gradients back from element records (a restored state).</summary>
        public void ImportGradients(TetGradients[] from)
        {
            int n = Count;
            for (int e = 0; e < n; e++)
            {
                ref TetGradients t = ref from[e];
                Set(0, e, t.D0);
                Set(3, e, t.D1);
                Set(6, e, t.D2);
                Set(9, e, t.D3);
                Set(12, e, t.H0);
                Set(15, e, t.H1);
                Set(18, e, t.H2);
                Set(21, e, t.H3);
                Gradients[24 * n + e] = t.KDD;
                Gradients[25 * n + e] = t.KDH;
                Gradients[26 * n + e] = t.KHH;
            }
        }

        /// <summary>Stores a 3-vector gradient field (first field <paramref name="field"/>) of element e.</summary>
        public void Set(int field, int e, Vector3 v)
        {
            int n = Count;
            Gradients[field * n + e] = v.X;
            Gradients[(field + 1) * n + e] = v.Y;
            Gradients[(field + 2) * n + e] = v.Z;
        }

        /// <summary>Reads a 3-vector gradient field of element e.</summary>
        public Vector3 Get(int field, int e)
        {
            int n = Count;
            return new Vector3(Gradients[field * n + e], Gradients[(field + 1) * n + e], Gradients[(field + 2) * n + e]);
        }
    }
}
