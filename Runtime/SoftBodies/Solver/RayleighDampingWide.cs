#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// <see cref="RayleighDamping.Tets"/> eight tets at a time (AVX), with the scalar pass's
    /// operations in its order, so the velocities are bit-identical to it (see <see cref="XpbdTetSolverWide"/>).
    /// </summary>
    internal static class RayleighDampingWide
    {
        /// <summary>Damps the whole blocks of eight in [start, end); returns where the rest begins.</summary>
        public static int Tets(float deviatoricStiffness, float hydrostaticStiffness, TetStream tets, Vector3[] x, Vector3[] v,
            int start, int end, float h, float dampingTime)
        {
            Vector256<float> invD = Vector256.Create(1f / (h * dampingTime * deviatoricStiffness));
            Vector256<float> invH = Vector256.Create(1f / (h * dampingTime * hydrostaticStiffness));
            var block = new TetLanes();
            int e = start;
            for (; e + 8 <= end; e += 8)
            {
                uint write = Impulses(ref block, tets, v, e, invD, invH);
                if (write != 0) TetLanes.Correct(ref block, tets, x, v, e, write);
            }
            return e;
        }

        // The dashpot impulses mu (the 2x2 solve) and the velocity changes p_k before the torque-free projection.
        [MethodImpl(MethodImplOptions.NoInlining)]
        static uint Impulses(ref TetLanes b, TetStream tets, Vector3[] v, int e, Vector256<float> invD, Vector256<float> invH)
        {
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            float[] g = tets.Gradients;
            Vector256<float> active = b.LoadInverseMasses(tets, e);
            if (active.ExtractMostSignificantBits() == 0) return 0;
            Lanes8 v0 = Lanes8.Gather(v, vertices, e), v1 = Lanes8.Gather(v, vertices, n + e);
            Lanes8 v2 = Lanes8.Gather(v, vertices, 2 * n + e), v3 = Lanes8.Gather(v, vertices, 3 * n + e);
            b.Base0 = v0;
            b.Base1 = v1;
            b.Base2 = v2;
            b.Base3 = v3;
            Lanes8 gD0 = Lanes8.Load(g, 0, n, e), gD1 = Lanes8.Load(g, 3, n, e), gD2 = Lanes8.Load(g, 6, n, e), gD3 = Lanes8.Load(g, 9, n, e);
            Lanes8 gH0 = Lanes8.Load(g, 12, n, e), gH1 = Lanes8.Load(g, 15, n, e), gH2 = Lanes8.Load(g, 18, n, e), gH3 = Lanes8.Load(g, 21, n, e);
            Vector256<float> sD = Lanes8.Dot(gD0, v0) + Lanes8.Dot(gD1, v1) + Lanes8.Dot(gD2, v2) + Lanes8.Dot(gD3, v3);
            Vector256<float> sH = Lanes8.Dot(gH0, v0) + Lanes8.Dot(gH1, v1) + Lanes8.Dot(gH2, v2) + Lanes8.Dot(gH3, v3);
            Vector256<float> invV = Vector256<float>.One / Lanes8.Load(tets.RestVolume, e);
            Vector256<float> a11 = Lanes8.Load(g, 24 * n + e) + invD * invV, a12 = Lanes8.Load(g, 25 * n + e), a22 = Lanes8.Load(g, 26 * n + e) + invH * invV;
            Vector256<float> det = a11 * a22 - a12 * a12;
            Vector256<float> solved = Vector256.GreaterThan(det, Vector256.Create(1e-30f) * a11 * a22) & active;
            uint write = solved.ExtractMostSignificantBits();
            if (write == 0) return 0;
            b.Solved = solved;
            Vector256<float> invDet = Vector256<float>.One / det;
            Vector256<float> mD = (sD * a22 - sH * a12) * invDet;
            Vector256<float> mH = (a11 * sH - a12 * sD) * invDet;
            b.G0 = -(mD * gD0 + mH * gH0);
            b.G1 = -(mD * gD1 + mH * gH1);
            b.G2 = -(mD * gD2 + mH * gH2);
            b.G3 = -(mD * gD3 + mH * gH3);
            return write;
        }
    }
}
#endif
