#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// What the eight-lane tet passes (<see cref="XpbdTetSolverWide"/>, <see cref="RayleighDampingWide"/>)
    /// carry to their last stage: the four vertices' inverse masses, the values the corrections
    /// add to (positions, or velocities), the corrections g_k themselves and the lanes solved;
    /// and that last stage, written once for both passes.
    /// </summary>
    internal struct TetLanes
    {
        /// <summary>The values the corrections add to: positions (XPBD) or velocities (damping).</summary>
        public Lanes8 Base0, Base1, Base2, Base3;
        /// <summary>The corrections before the torque-free projection (impulses g_k, times w_k when written).</summary>
        public Lanes8 G0, G1, G2, G3;
        /// <summary>The vertices' inverse masses.</summary>
        public Vector256<float> W0, W1, W2, W3;
        /// <summary>The lanes whose system was solved (a comparison mask).</summary>
        public Vector256<float> Solved;

        /// <summary>Loads the inverse masses of tets e .. e + 7; returns the lanes with a free vertex (a comparison mask).</summary>
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

        /// <summary>
        /// The corrections made torque-free about the positions <paramref name="about"/> (in the
        /// solved lanes whose tet is free; <see cref="TorqueFreeWide"/>), then
        /// Base_k + w_k g_k written to <paramref name="target"/> in the lanes of <paramref name="write"/>.
        /// Not inlined: each pass's stages register-allocate on their own.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static void Correct(ref TetLanes b, TetStream tets, Vector3[] about, Vector3[] target, int e, uint write)
        {
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            float[] masses = tets.ElementMasses;
            Vector256<float> free = Vector256.GreaterThan(Lanes8.Load(masses, 8 * n + e), Vector256<float>.Zero) & b.Solved;
            Lanes8 g0 = b.G0, g1 = b.G1, g2 = b.G2, g3 = b.G3;
            if (free.ExtractMostSignificantBits() != 0)
            {
                Lanes8 p0 = Lanes8.Gather(about, vertices, e), p1 = Lanes8.Gather(about, vertices, n + e);
                Lanes8 p2 = Lanes8.Gather(about, vertices, 2 * n + e), p3 = Lanes8.Gather(about, vertices, 3 * n + e);
                TorqueFreeWide.Project(p0, p1, p2, p3, Lanes8.Load(masses, 4 * n + e), Lanes8.Load(masses, 5 * n + e), Lanes8.Load(masses, 6 * n + e), Lanes8.Load(masses, 7 * n + e), free, ref g0, ref g1, ref g2, ref g3);
            }
            Lanes8.Scatter(target, vertices, e, write, b.Base0 + b.W0 * g0);
            Lanes8.Scatter(target, vertices, n + e, write, b.Base1 + b.W1 * g1);
            Lanes8.Scatter(target, vertices, 2 * n + e, write, b.Base2 + b.W2 * g2);
            Lanes8.Scatter(target, vertices, 3 * n + e, write, b.Base3 + b.W3 * g3);
        }
    }
}
#endif
