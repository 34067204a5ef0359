#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using Fulcrum.Dynamics;
using System.Runtime.Intrinsics.X86;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Eight 3-vectors side by side (x, y and z each a 256-bit register) and the moves of
    /// per-vertex data in and out of eight lanes: eight 16-byte loads and a 4x4 transpose per
    /// 128-bit half (AVX) give one quantity's x, y, z (and w) for all lanes. Pure data movement
    /// and the same float operations in the same order as <see cref="System.Numerics.Vector3"/>,
    /// so the wide kernels give results bit-identical to the scalar ones.
    /// </summary>
    internal struct Lanes8
    {
        public Vector256<float> X, Y, Z;

        /// <summary>The wide kernels run where AVX is (the transposes need it).</summary>
        public static bool IsSupported => Avx.IsSupported;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Lanes8(Vector256<float> x, Vector256<float> y, Vector256<float> z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 operator +(in Lanes8 a, in Lanes8 b) => new Lanes8(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 operator -(in Lanes8 a, in Lanes8 b) => new Lanes8(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 operator -(in Lanes8 a) => new Lanes8(-a.X, -a.Y, -a.Z);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 operator *(Vector256<float> s, in Lanes8 a) => new Lanes8(s * a.X, s * a.Y, s * a.Z);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 operator *(in Lanes8 a, Vector256<float> s) => new Lanes8(a.X * s, a.Y * s, a.Z * s);

        /// <summary>Componentwise product (Vector3 * Vector3).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 operator *(in Lanes8 a, in Lanes8 b) => new Lanes8(a.X * b.X, a.Y * b.Y, a.Z * b.Z);

        /// <summary>(x x + y y) + z z, the order of Vector3.Dot.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector256<float> Dot(in Lanes8 a, in Lanes8 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 Cross(in Lanes8 a, in Lanes8 b) =>
            new Lanes8(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

        /// <summary>Per lane a where the mask is set, else b.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 Select(Vector256<float> mask, in Lanes8 a, in Lanes8 b) =>
            new Lanes8(Avx.BlendVariable(b.X, a.X, mask), Avx.BlendVariable(b.Y, a.Y, mask), Avx.BlendVariable(b.Z, a.Z, mask));

        /// <summary>Eight floats of one field from <paramref name="array"/>[<paramref name="at"/>].</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector256<float> Load(float[] array, int at) => Vector256.LoadUnsafe(ref MemoryMarshal.GetArrayDataReference(array), (nuint)at);

        /// <summary>Three consecutive fields (x, y, z runs of <paramref name="n"/>) at element <paramref name="at"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 Load(float[] array, int field, int n, int at) =>
            new Lanes8(Load(array, field * n + at), Load(array, (field + 1) * n + at), Load(array, (field + 2) * n + at));

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Store(float[] array, int at, Vector256<float> value) => value.StoreUnsafe(ref MemoryMarshal.GetArrayDataReference(array), (nuint)at);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Store(float[] array, int field, int n, int at, in Lanes8 value)
        {
            Store(array, field * n + at, value.X);
            Store(array, (field + 1) * n + at, value.Y);
            Store(array, (field + 2) * n + at, value.Z);
        }

        /// <summary>
        /// The vertices <paramref name="index"/>[at .. at + 7] of a Vector3 array, as lanes. Unchecked: the
        /// indices are vertex indices of the body's own (validated) elements, and <paramref name="at"/> + 7 is inside the run.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Lanes8 Gather(Vector3[] v, int[] index, int at)
        {
            ref Vector3 b = ref MemoryMarshal.GetArrayDataReference(v);
            ref int i = ref Unsafe.Add(ref MemoryMarshal.GetArrayDataReference(index), at);
            Vector256<float> m0 = Vector256.Create(Unsafe.Add(ref b, i).AsVector128Unsafe(), Unsafe.Add(ref b, Unsafe.Add(ref i, 4)).AsVector128Unsafe());
            Vector256<float> m1 = Vector256.Create(Unsafe.Add(ref b, Unsafe.Add(ref i, 1)).AsVector128Unsafe(), Unsafe.Add(ref b, Unsafe.Add(ref i, 5)).AsVector128Unsafe());
            Vector256<float> m2 = Vector256.Create(Unsafe.Add(ref b, Unsafe.Add(ref i, 2)).AsVector128Unsafe(), Unsafe.Add(ref b, Unsafe.Add(ref i, 6)).AsVector128Unsafe());
            Vector256<float> m3 = Vector256.Create(Unsafe.Add(ref b, Unsafe.Add(ref i, 3)).AsVector128Unsafe(), Unsafe.Add(ref b, Unsafe.Add(ref i, 7)).AsVector128Unsafe());
            SolverBodyLanes.Transpose(m0, m1, m2, m3, out Vector256<float> x, out Vector256<float> y, out Vector256<float> z, out _);
            return new Lanes8(x, y, z);
        }

        /// <summary>Writes lanes back to the vertices <paramref name="index"/>[at .. at + 7] whose bit is set in <paramref name="write"/>; unchecked as above.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Scatter(Vector3[] v, int[] index, int at, uint write, in Lanes8 value)
        {
            SolverBodyLanes.Transpose(value.X, value.Y, value.Z, value.Z, out Vector256<float> r04, out Vector256<float> r15, out Vector256<float> r26, out Vector256<float> r37);
            ref Vector3 b = ref MemoryMarshal.GetArrayDataReference(v);
            ref int i = ref Unsafe.Add(ref MemoryMarshal.GetArrayDataReference(index), at);
            if ((write & 1) != 0) Unsafe.Add(ref b, i) = r04.GetLower().AsVector3();
            if ((write & 2) != 0) Unsafe.Add(ref b, Unsafe.Add(ref i, 1)) = r15.GetLower().AsVector3();
            if ((write & 4) != 0) Unsafe.Add(ref b, Unsafe.Add(ref i, 2)) = r26.GetLower().AsVector3();
            if ((write & 8) != 0) Unsafe.Add(ref b, Unsafe.Add(ref i, 3)) = r37.GetLower().AsVector3();
            if ((write & 16) != 0) Unsafe.Add(ref b, Unsafe.Add(ref i, 4)) = r04.GetUpper().AsVector3();
            if ((write & 32) != 0) Unsafe.Add(ref b, Unsafe.Add(ref i, 5)) = r15.GetUpper().AsVector3();
            if ((write & 64) != 0) Unsafe.Add(ref b, Unsafe.Add(ref i, 6)) = r26.GetUpper().AsVector3();
            if ((write & 128) != 0) Unsafe.Add(ref b, Unsafe.Add(ref i, 7)) = r37.GetUpper().AsVector3();
        }
    }
}
#endif
