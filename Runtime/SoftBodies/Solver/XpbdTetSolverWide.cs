#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// <see cref="XpbdTetSolver"/> for the stable Neo-Hookean model, eight tets of one colour
    /// at a time (AVX): vertex data moved into lanes by transposes (<see cref="Lanes8"/>), the
    /// element data read straight from <see cref="TetStream"/>'s runs, and the corrections
    /// written back lane by lane (the elements of a colour share no vertex, so the writes
    /// never collide); the vertices' masses are loaded per element (<see cref="TetStream.ElementMasses"/>).
    /// Every operation is the scalar kernel's, in its order (no fused multiply-add; the
    /// deviatoric constraint in float as <see cref="StableDeviatoric"/> has it, its logarithm
    /// per lane only in the rare lanes beyond the series), so the results are bit-identical to
    /// it and the solve does not depend on how a colour is split into blocks, chunks or threads. Lanes near the <see cref="VolumeFloor"/> are then held above
    /// it by the scalar projection.
    /// </summary>
    internal static class XpbdTetSolverWide
    {
        /// <summary>
        /// Solves the whole blocks of eight in [start, end); returns where the rest (fewer
        /// than eight, for the scalar kernel) begins.
        /// </summary>
        public static int Solve(in StableNeoHookeanEnergy model, TetStream tets, Vector2[] lambdas, bool keep, Vector3[] x, Vector3[] xPrev,
            int start, int end, float h)
        {
            float invH2 = 1f / (h * h);
            var k = new Constants
            {
                AlphaDev = Vector256.Create(invH2 / model.DeviatoricStiffness),
                AlphaVol = Vector256.Create(invH2 / model.HydrostaticStiffness),
                Beta = Vector256.Create(model.Beta),
            };
            var block = new Block();
            Vector256<float> floorTrigger = Vector256.Create(VolumeFloor.Trigger - 1f);
            bool loaded = tets.Loaded; // the floor holds only a body something presses
            int e = start;
            for (; e + 8 <= end; e += 8)
            {
                if (!Gradients(ref block, k, tets, x, e)) continue;
                uint write = Multipliers(ref block, k, tets, lambdas, keep, e);
                if (write != 0) TetLanes.Correct(ref block.T, tets, xPrev, x, e, write);
                // Lanes near the volume floor (J below its trigger before the projection), one by one.
                if (!loaded) continue;
                uint low = (Vector256.LessThan(block.CH, floorTrigger) & block.Active).ExtractMostSignificantBits();
                while (low != 0)
                {
                    int lane = BitOperations.TrailingZeroCount(low);
                    low &= low - 1;
                    VolumeFloor.Hold(tets, e + lane, x);
                }
            }
            return e;
        }

        struct Constants
        {
            public Vector256<float> AlphaDev, AlphaVol, Beta;
        }

        // One block's values between the stages. The kernel is split into three methods so
        // that the JIT inlines every helper inside each (one method of the whole kernel runs
        // past its inlining limits and leaves calls and spills in the loop).
        struct Block
        {
            public TetLanes T;
            public Lanes8 D0, D1, D2, D3, H0, H1, H2, H3;
            public Vector256<float> Active, CD, CH;
            public bool All;
        }

        // Inverse masses, positions, F, the constraints and their vertex gradients; false when every lane is pinned.
        [MethodImpl(MethodImplOptions.NoInlining)]
        static bool Gradients(ref Block b, in Constants k, TetStream tets, Vector3[] x, int e)
        {
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            Vector256<float> active = b.T.LoadInverseMasses(tets, e);
            uint activeBits = active.ExtractMostSignificantBits();
            if (activeBits == 0) return false;
            b.Active = active;
            b.All = activeBits == 0xFF;

            Lanes8 x0 = Lanes8.Gather(x, vertices, e), x1 = Lanes8.Gather(x, vertices, n + e);
            Lanes8 x2 = Lanes8.Gather(x, vertices, 2 * n + e), x3 = Lanes8.Gather(x, vertices, 3 * n + e);
            b.T.Base0 = x0;
            b.T.Base1 = x1;
            b.T.Base2 = x2;
            b.T.Base3 = x3;
            float[] rest = tets.RestInverse;
            Lanes8 r0 = Lanes8.Load(rest, 0, n, e), r1 = Lanes8.Load(rest, 3, n, e), r2 = Lanes8.Load(rest, 6, n, e);
            // F = Ds Dm^-1, column j = Ds (column j of Dm^-1).
            Lanes8 e0 = x1 - x0, e1 = x2 - x0, e2 = x3 - x0;
            Lanes8 f0 = e0 * r0.X + e1 * r0.Y + e2 * r0.Z;
            Lanes8 f1 = e0 * r1.X + e1 * r1.Y + e2 * r1.Z;
            Lanes8 f2 = e0 * r2.X + e1 * r2.Y + e2 * r2.Z;
            // cof F (= dC_H/dF).
            Lanes8 k0 = Lanes8.Cross(f1, f2), k1 = Lanes8.Cross(f2, f0), k2 = Lanes8.Cross(f0, f1);

            // The deviatoric constraint (StableDeviatoric.Evaluate, lane by lane).
            Vector256<float> dev = Deviatoric(f0, f1, f2, k.Beta, out Vector256<float> c, out Vector256<float> s, out Vector256<float> t, out Vector256<float> j);
            b.CD = c;
            b.CH = j;
            Lanes8 zero = default;
            Lanes8 dD0 = Lanes8.Select(dev, f0 * s + k0 * t, zero);
            Lanes8 dD1 = Lanes8.Select(dev, f1 * s + k1 * t, zero);
            Lanes8 dD2 = Lanes8.Select(dev, f2 * s + k2 * t, zero);
            VertexGradients(dD0, dD1, dD2, r0, r1, r2, out b.D0, out b.D1, out b.D2, out b.D3);
            VertexGradients(k0, k1, k2, r0, r1, r2, out b.H0, out b.H1, out b.H2, out b.H3);
            return true;
        }

        // The 2x2 multiplier update (XpbdConstraintPair) and the impulses g_k; returns the lanes to write.
        [MethodImpl(MethodImplOptions.NoInlining)]
        static uint Multipliers(ref Block b, in Constants k, TetStream tets, Vector2[] lambdas, bool keep, int e)
        {
            int n = tets.Count;
            Vector256<float> w0 = b.T.W0, w1 = b.T.W1, w2 = b.T.W2, w3 = b.T.W3;
            Vector256<float> kDD = w0 * Lanes8.Dot(b.D0, b.D0) + w1 * Lanes8.Dot(b.D1, b.D1) + w2 * Lanes8.Dot(b.D2, b.D2) + w3 * Lanes8.Dot(b.D3, b.D3);
            Vector256<float> kHH = w0 * Lanes8.Dot(b.H0, b.H0) + w1 * Lanes8.Dot(b.H1, b.H1) + w2 * Lanes8.Dot(b.H2, b.H2) + w3 * Lanes8.Dot(b.H3, b.H3);
            Vector256<float> kDH = w0 * Lanes8.Dot(b.D0, b.H0) + w1 * Lanes8.Dot(b.D1, b.H1) + w2 * Lanes8.Dot(b.D2, b.H2) + w3 * Lanes8.Dot(b.D3, b.H3);
            if (keep) Keep(tets.Gradients, n, e, b.Active, b.All, b.D0, b.D1, b.D2, b.D3, b.H0, b.H1, b.H2, b.H3, kDD, kDH, kHH);

            Vector256<float> invV = Vector256<float>.One / Lanes8.Load(tets.RestVolume, e);
            Vector256<float> aD = k.AlphaDev * invV, aH = k.AlphaVol * invV;
            ref float lambda = ref Unsafe.As<Vector2, float>(ref lambdas[e]);
            Vector256<float> lo = Vector256.LoadUnsafe(ref lambda), hi = Vector256.LoadUnsafe(ref lambda, 8);
            // De-interleave (X, Y) pairs: shuffle within 128-bit halves, then put the 64-bit pieces in order.
            Vector256<float> lambdaD = Avx2.Permute4x64(Avx.Shuffle(lo, hi, 0x88).AsDouble(), 0xD8).AsSingle();
            Vector256<float> lambdaH = Avx2.Permute4x64(Avx.Shuffle(lo, hi, 0xDD).AsDouble(), 0xD8).AsSingle();
            Vector256<float> rD = -b.CD - aD * lambdaD;
            Vector256<float> rH = -b.CH - aH * lambdaH;
            Vector256<float> a11 = kDD + aD, a22 = kHH + aH;
            Vector256<float> det = a11 * a22 - kDH * kDH;
            Vector256<float> solved = Vector256.GreaterThan(det, Vector256.Create(1e-30f) * a11 * a22) & b.Active;
            uint write = solved.ExtractMostSignificantBits();
            if (write == 0) return 0;
            b.T.Solved = solved;
            Vector256<float> invDet = Vector256<float>.One / det;
            Vector256<float> dlD = Avx.BlendVariable(Vector256<float>.Zero, (rD * a22 - rH * kDH) * invDet, solved);
            Vector256<float> dlH = Avx.BlendVariable(Vector256<float>.Zero, (a11 * rH - kDH * rD) * invDet, solved);
            // Lambda is never -0 (it starts at +0), so adding the +0 of an unsolved lane keeps its bits.
            Vector256<float> newD = Avx2.Permute4x64((lambdaD + dlD).AsDouble(), 0xD8).AsSingle();
            Vector256<float> newH = Avx2.Permute4x64((lambdaH + dlH).AsDouble(), 0xD8).AsSingle();
            Avx.UnpackLow(newD, newH).StoreUnsafe(ref lambda);
            Avx.UnpackHigh(newD, newH).StoreUnsafe(ref lambda, 8);
            b.T.G0 = dlD * b.D0 + dlH * b.H0;
            b.T.G1 = dlD * b.D1 + dlH * b.H1;
            b.T.G2 = dlD * b.D2 + dlH * b.H2;
            b.T.G3 = dlD * b.D3 + dlH * b.H3;
            return write;
        }

        // StableDeviatoric.Evaluate for eight lanes: the mask of lanes off rest, C_D (0 at rest), s, t and j = J - 1.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector256<float> Deviatoric(in Lanes8 f0, in Lanes8 f1, in Lanes8 f2, Vector256<float> beta,
            out Vector256<float> c, out Vector256<float> s, out Vector256<float> t, out Vector256<float> j)
        {
            Vector256<float> one = Vector256<float>.One;
            Vector256<float> h00 = f0.X - one, h10 = f0.Y, h20 = f0.Z;
            Vector256<float> h01 = f1.X, h11 = f1.Y - one, h21 = f1.Z;
            Vector256<float> h02 = f2.X, h12 = f2.Y, h22 = f2.Z - one;
            Vector256<float> tr = h00 + h11 + h22;
            Vector256<float> sq = h00 * h00 + h10 * h10 + h20 * h20 + h01 * h01 + h11 * h11 + h21 * h21 + h02 * h02 + h12 * h12 + h22 * h22;
            Vector256<float> minors = h00 * h11 - h01 * h10 + h11 * h22 - h12 * h21 + h00 * h22 - h02 * h20;
            Vector256<float> det = h00 * (h11 * h22 - h12 * h21) - h01 * (h10 * h22 - h12 * h20) + h02 * (h10 * h21 - h11 * h20);
            Vector256<float> higher = minors + det;
            j = tr + higher;
            Vector256<float> a = Vector256.Create(2f) * tr + sq;
            Vector256<float> u = Vector256.Create(0.25f) * a;
            Vector256<float> w = u / (Vector256.Create(2f) + u);
            // StableDeviatoric.Series, and Direct in the lanes beyond its limit.
            Vector256<float> z = w * w;
            Vector256<float> p = (((z * Vector256.Create(1f / 11f) + Vector256.Create(1f / 9f)) * z + Vector256.Create(1f / 7f)) * z
                + Vector256.Create(1f / 5f)) * z + Vector256.Create(1f / 3f);
            Vector256<float> log = w * (u - Vector256.Create(2f) * z * p);
            Vector256<float> series = Vector256.LessThanOrEqual(Vector256.Abs(w), Vector256.Create(StableDeviatoric.SeriesLimit));
            if (series.ExtractMostSignificantBits() != 0xFF) log = DirectLanes(log, u, series);
            Vector256<float> d = log + (Vector256.Create(0.75f) * sq - Vector256.Create(1.5f) * higher) + beta * j * j;
            Vector256<float> on = Vector256.GreaterThan(d, Vector256.Create((float)DeformationGradient.RestTolerance));
            // Lanes at rest get C_D = 0 and s = t = 0 (the square root and quotients of those lanes are discarded).
            Vector256<float> cOn = Vector256.Sqrt(Vector256.Max(d, Vector256<float>.Zero));
            c = Avx.BlendVariable(Vector256<float>.Zero, cOn, on);
            s = Avx.BlendVariable(Vector256<float>.Zero, (Vector256.Create(3f) + a) / ((Vector256.Create(4f) + a) * cOn), on);
            t = Avx.BlendVariable(Vector256<float>.Zero, (Vector256.Create(2f) * beta * j - Vector256.Create(1.5f)) / (Vector256.Create(2f) * cOn), on);
            return on;
        }

        // StableDeviatoric.Direct in the lanes not set in the mask.
        [MethodImpl(MethodImplOptions.NoInlining)]
        static Vector256<float> DirectLanes(Vector256<float> log, Vector256<float> u, Vector256<float> series)
        {
            uint bits = series.ExtractMostSignificantBits();
            for (int lane = 0; lane < 8; lane++)
                if ((bits & (1u << lane)) == 0) log = log.WithElement(lane, StableDeviatoric.Direct(u.GetElement(lane)));
            return log;
        }

        // DeformationGradient.VertexGradients: g_k = G (row k of Dm^-1), g_0 = -(g_1 + g_2 + g_3).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void VertexGradients(in Lanes8 g0c, in Lanes8 g1c, in Lanes8 g2c, in Lanes8 r0, in Lanes8 r1, in Lanes8 r2,
            out Lanes8 v0, out Lanes8 v1, out Lanes8 v2, out Lanes8 v3)
        {
            v1 = g0c * r0.X + g1c * r1.X + g2c * r2.X;
            v2 = g0c * r0.Y + g1c * r1.Y + g2c * r2.Y;
            v3 = g0c * r0.Z + g1c * r1.Z + g2c * r2.Z;
            v0 = -(v1 + v2 + v3);
        }

        // Stores the gradients for the damping pass; lanes of fully pinned tets keep their old values (as the scalar kernel does).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Keep(float[] g, int n, int e, Vector256<float> active, bool all, in Lanes8 d0, in Lanes8 d1, in Lanes8 d2, in Lanes8 d3,
            in Lanes8 h0, in Lanes8 h1, in Lanes8 h2, in Lanes8 h3, Vector256<float> kDD, Vector256<float> kDH, Vector256<float> kHH)
        {
            Put(g, n, e, 0, active, all, d0);
            Put(g, n, e, 3, active, all, d1);
            Put(g, n, e, 6, active, all, d2);
            Put(g, n, e, 9, active, all, d3);
            Put(g, n, e, 12, active, all, h0);
            Put(g, n, e, 15, active, all, h1);
            Put(g, n, e, 18, active, all, h2);
            Put(g, n, e, 21, active, all, h3);
            Put(g, 24 * n + e, active, all, kDD);
            Put(g, 25 * n + e, active, all, kDH);
            Put(g, 26 * n + e, active, all, kHH);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Put(float[] g, int n, int e, int field, Vector256<float> active, bool all, in Lanes8 v)
        {
            Put(g, field * n + e, active, all, v.X);
            Put(g, (field + 1) * n + e, active, all, v.Y);
            Put(g, (field + 2) * n + e, active, all, v.Z);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Put(float[] g, int at, Vector256<float> active, bool all, Vector256<float> v)
        {
            if (!all) v = Avx.BlendVariable(Lanes8.Load(g, at), v, active);
            Lanes8.Store(g, at, v);
        }
    }
}
#endif
