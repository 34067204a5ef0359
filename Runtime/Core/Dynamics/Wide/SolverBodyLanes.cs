#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Moves solver bodies into and out of SIMD lanes with 4x4 transposes (AVX, eight lanes):
    /// a body's velocity, angular velocity, displacement and rotation each start on a 16-byte
    /// boundary of <see cref="SolverBody"/>, so eight 16-byte loads and a transpose give one
    /// quantity's x, y, z (and w) for all lanes, where lane-by-lane inserts would go through
    /// memory one float at a time. Pure data movement: results are bit-identical to the
    /// lane-by-lane path, which stays for other vector widths.
    /// </summary>
    internal static class SolverBodyLanes
    {
        /// <summary>Whether the transposing path applies (AVX with eight-float vectors).</summary>
        public static bool IsSupported => Avx.IsSupported && Vector<float>.Count == 8;

        // Float offsets inside SolverBody (see its layout): LinearVelocity, AngularVelocity,
        // the block whose last three floats are DeltaPosition, DeltaRotation.
        public const int Linear = 0, Angular = 4, Inertia = 8, Displacement = 16, Rotation = 20;

        /// <summary>The first float of the solver body that <paramref name="laneBodies"/>[<paramref name="at"/>] names.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static ref float Body(SolverBody[] bodies, int[] laneBodies, int at) =>
            ref Unsafe.As<SolverBody, float>(ref bodies[laneBodies[at]]);

        /// <summary>
        /// Four floats at <paramref name="offset"/> of each of eight bodies, transposed: x holds
        /// every lane's first float, and so on.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Load(ref float b0, ref float b1, ref float b2, ref float b3, ref float b4, ref float b5, ref float b6, ref float b7,
            int offset, out Vector<float> x, out Vector<float> y, out Vector<float> z, out Vector<float> w)
        {
            nuint o = (nuint)offset;
            Vector256<float> m0 = Vector256.Create(Vector128.LoadUnsafe(ref b0, o), Vector128.LoadUnsafe(ref b4, o));
            Vector256<float> m1 = Vector256.Create(Vector128.LoadUnsafe(ref b1, o), Vector128.LoadUnsafe(ref b5, o));
            Vector256<float> m2 = Vector256.Create(Vector128.LoadUnsafe(ref b2, o), Vector128.LoadUnsafe(ref b6, o));
            Vector256<float> m3 = Vector256.Create(Vector128.LoadUnsafe(ref b3, o), Vector128.LoadUnsafe(ref b7, o));
            Transpose(m0, m1, m2, m3, out Vector256<float> tx, out Vector256<float> ty, out Vector256<float> tz, out Vector256<float> tw);
            x = tx.AsVector();
            y = ty.AsVector();
            z = tz.AsVector();
            w = tw.AsVector();
        }

        /// <summary>
        /// The inverse of <see cref="Load"/> for the bodies whose <paramref name="write"/> flag is
        /// set: four floats back to <paramref name="offset"/> of each.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Store(ref float b0, ref float b1, ref float b2, ref float b3, ref float b4, ref float b5, ref float b6, ref float b7,
            int write, int offset, Vector<float> x, Vector<float> y, Vector<float> z, Vector<float> w)
        {
            Transpose(x.AsVector256(), y.AsVector256(), z.AsVector256(), w.AsVector256(),
                out Vector256<float> r04, out Vector256<float> r15, out Vector256<float> r26, out Vector256<float> r37);
            nuint o = (nuint)offset;
            if ((write & 1) != 0) r04.GetLower().StoreUnsafe(ref b0, o);
            if ((write & 2) != 0) r15.GetLower().StoreUnsafe(ref b1, o);
            if ((write & 4) != 0) r26.GetLower().StoreUnsafe(ref b2, o);
            if ((write & 8) != 0) r37.GetLower().StoreUnsafe(ref b3, o);
            if ((write & 16) != 0) r04.GetUpper().StoreUnsafe(ref b4, o);
            if ((write & 32) != 0) r15.GetUpper().StoreUnsafe(ref b5, o);
            if ((write & 64) != 0) r26.GetUpper().StoreUnsafe(ref b6, o);
            if ((write & 128) != 0) r37.GetUpper().StoreUnsafe(ref b7, o);
        }

        // 4x4 transposes within both 128-bit halves at once (the soft bodies' Lanes8 uses it too).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static void Transpose(Vector256<float> a, Vector256<float> b, Vector256<float> c, Vector256<float> d,
            out Vector256<float> x, out Vector256<float> y, out Vector256<float> z, out Vector256<float> w)
        {
            Vector256<float> t0 = Avx.UnpackLow(a, b);
            Vector256<float> t1 = Avx.UnpackHigh(a, b);
            Vector256<float> t2 = Avx.UnpackLow(c, d);
            Vector256<float> t3 = Avx.UnpackHigh(c, d);
            x = Avx.Shuffle(t0, t2, 0x44);
            y = Avx.Shuffle(t0, t2, 0xEE);
            z = Avx.Shuffle(t1, t3, 0x44);
            w = Avx.Shuffle(t1, t3, 0xEE);
        }
    }
}
#endif
