#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The four vertices of a block of eight tets (elements e .. e + 7 of one colour) in lanes, as
    /// both wide tet kernels (<see cref="XpbdTetSolverWide"/>, <see cref="RayleighDampingWide"/>)
    /// carry them from their first stage into their last: each vertex's value before the
    /// correction (a position, or a velocity), its inverse mass and its impulse. The loads and
    /// the last stage, the torque-free projection and the writes, are the same in both kernels,
    /// so they live here once.
    /// </summary>
    internal struct TetVertexLanes
    {
        /// <summary>The values the correction moves (positions or velocities) of vertices A, B, C, D.</summary>
        public Lanes8 Y0, Y1, Y2, Y3;

        /// <summary>The inverse masses W of vertices A, B, C, D.</summary>
        public Vector256<float> W0, W1, W2, W3;

        /// <summary>The impulses g_k of vertices A, B, C, D before the torque-free projection (a value moves by W g).</summary>
        public Lanes8 G0, G1, G2, G3;

        /// <summary>The lanes whose 2x2 solve succeeded (a comparison mask).</summary>
        public Vector256<float> Solved;

        /// <summary>Loads <see cref="W0"/> .. <see cref="W3"/>; returns the mask of lanes with a vertex that is not pinned.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector256<float> LoadInverseMasses(TetStream tets, int e)
        {
            int n = tets.Count;
            float[] masses = tets.ElementMasses;
            W0 = Lanes8.Load(masses, e);
            W1 = Lanes8.Load(masses, n + e);
            W2 = Lanes8.Load(masses, 2 * n + e);
            W3 = Lanes8.Load(masses, 3 * n + e);
            return ~Vector256.Equals(W0 + W1 + W2 + W3, Vector256<float>.Zero);
        }

        /// <summary>The block's vertices A, B, C, D of a per-vertex array, as lanes.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Gather(Vector3[] values, TetStream tets, int e, out Lanes8 v0, out Lanes8 v1, out Lanes8 v2, out Lanes8 v3)
        {
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            v0 = Lanes8.Gather(values, vertices, e);
            v1 = Lanes8.Gather(values, vertices, n + e);
            v2 = Lanes8.Gather(values, vertices, 2 * n + e);
            v3 = Lanes8.Gather(values, vertices, 3 * n + e);
        }

        /// <summary>
        /// The last stage: the impulses made free of net torque about the positions
        /// <paramref name="about"/> in the solved lanes whose four vertices are all free
        /// (<see cref="TetStream.ElementMasses"/> field 8), then Y + W g written to
        /// <paramref name="values"/> in the lanes set in <paramref name="write"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public void Correct(TetStream tets, Vector3[] about, Vector3[] values, int e, uint write)
        {
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            float[] masses = tets.ElementMasses;
            Vector256<float> free = Vector256.GreaterThan(Lanes8.Load(masses, 8 * n + e), Vector256<float>.Zero) & Solved;
            Lanes8 g0 = G0, g1 = G1, g2 = G2, g3 = G3;
            if (free.ExtractMostSignificantBits() != 0)
            {
                Gather(about, tets, e, out Lanes8 p0, out Lanes8 p1, out Lanes8 p2, out Lanes8 p3);
                TorqueFreeWide.Project(p0, p1, p2, p3, Lanes8.Load(masses, 4 * n + e), Lanes8.Load(masses, 5 * n + e), Lanes8.Load(masses, 6 * n + e), Lanes8.Load(masses, 7 * n + e), free, ref g0, ref g1, ref g2, ref g3);
            }
            Lanes8.Scatter(values, vertices, e, write, Y0 + W0 * g0);
            Lanes8.Scatter(values, vertices, n + e, write, Y1 + W1 * g1);
            Lanes8.Scatter(values, vertices, 2 * n + e, write, Y2 + W2 * g2);
            Lanes8.Scatter(values, vertices, 3 * n + e, write, Y3 + W3 * g3);
        }
    }
}
#endif
