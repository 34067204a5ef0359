#if NET
using System.Numerics;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

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
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            float[] g = tets.Gradients;
            Vector4[] masses = tets.Masses;
            int e = start;
            for (; e + 8 <= end; e += 8)
            {
                Lanes8 mass0 = Lanes8.Gather(masses, vertices, e), mass1 = Lanes8.Gather(masses, vertices, n + e);
                Lanes8 mass2 = Lanes8.Gather(masses, vertices, 2 * n + e), mass3 = Lanes8.Gather(masses, vertices, 3 * n + e);
                Vector256<float> w0 = mass0.X, w1 = mass1.X, w2 = mass2.X, w3 = mass3.X;
                Vector256<float> active = ~Vector256.Equals(w0 + w1 + w2 + w3, Vector256<float>.Zero);
                if (active.ExtractMostSignificantBits() == 0) continue;
                Lanes8 gD0 = Lanes8.Load(g, 0, n, e), gD1 = Lanes8.Load(g, 3, n, e), gD2 = Lanes8.Load(g, 6, n, e), gD3 = Lanes8.Load(g, 9, n, e);
                Lanes8 gH0 = Lanes8.Load(g, 12, n, e), gH1 = Lanes8.Load(g, 15, n, e), gH2 = Lanes8.Load(g, 18, n, e), gH3 = Lanes8.Load(g, 21, n, e);
                Lanes8 v0 = Lanes8.Gather(v, vertices, e), v1 = Lanes8.Gather(v, vertices, n + e);
                Lanes8 v2 = Lanes8.Gather(v, vertices, 2 * n + e), v3 = Lanes8.Gather(v, vertices, 3 * n + e);
                Vector256<float> sD = Lanes8.Dot(gD0, v0) + Lanes8.Dot(gD1, v1) + Lanes8.Dot(gD2, v2) + Lanes8.Dot(gD3, v3);
                Vector256<float> sH = Lanes8.Dot(gH0, v0) + Lanes8.Dot(gH1, v1) + Lanes8.Dot(gH2, v2) + Lanes8.Dot(gH3, v3);
                Vector256<float> invV = Vector256<float>.One / Lanes8.Load(tets.RestVolume, e);
                Vector256<float> a11 = Lanes8.Load(g, 24 * n + e) + invD * invV, a12 = Lanes8.Load(g, 25 * n + e), a22 = Lanes8.Load(g, 26 * n + e) + invH * invV;
                Vector256<float> det = a11 * a22 - a12 * a12;
                Vector256<float> solved = Vector256.GreaterThan(det, Vector256.Create(1e-30f) * a11 * a22) & active;
                uint writeBits = solved.ExtractMostSignificantBits();
                if (writeBits == 0) continue;
                Vector256<float> invDet = Vector256<float>.One / det;
                Vector256<float> mD = (sD * a22 - sH * a12) * invDet;
                Vector256<float> mH = (a11 * sH - a12 * sD) * invDet;
                Lanes8 p0 = -(mD * gD0 + mH * gH0), p1 = -(mD * gD1 + mH * gH1), p2 = -(mD * gD2 + mH * gH2), p3 = -(mD * gD3 + mH * gH3);
                Vector256<float> free = Vector256.GreaterThan(mass0.Y, Vector256<float>.Zero) & Vector256.GreaterThan(mass1.Y, Vector256<float>.Zero)
                    & Vector256.GreaterThan(mass2.Y, Vector256<float>.Zero) & Vector256.GreaterThan(mass3.Y, Vector256<float>.Zero) & solved;
                if (free.ExtractMostSignificantBits() != 0)
                {
                    Lanes8 x0 = Lanes8.Gather(x, vertices, e), x1 = Lanes8.Gather(x, vertices, n + e);
                    Lanes8 x2 = Lanes8.Gather(x, vertices, 2 * n + e), x3 = Lanes8.Gather(x, vertices, 3 * n + e);
                    TorqueFreeWide.Project(x0, x1, x2, x3, mass0.Z, mass1.Z, mass2.Z, mass3.Z, free, ref p0, ref p1, ref p2, ref p3);
                }
                Lanes8.Scatter(v, vertices, e, writeBits, v0 + w0 * p0);
                Lanes8.Scatter(v, vertices, n + e, writeBits, v1 + w1 * p1);
                Lanes8.Scatter(v, vertices, 2 * n + e, writeBits, v2 + w2 * p2);
                Lanes8.Scatter(v, vertices, 3 * n + e, writeBits, v3 + w3 * p3);
            }
            return e;
        }
    }
}
#endif
