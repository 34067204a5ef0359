#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Vector&lt;float&gt;.Count 3-vectors side by side (x, y and z each a SIMD register): the one
    /// small wide-float vocabulary of <see cref="ContactSolverWide"/>.
    /// </summary>
    internal struct WideVector3
    {
        public Vector<float> X, Y, Z;

        /// <summary>
        /// Per lane, <paramref name="a"/> where <paramref name="mask"/> is set and <paramref name="b"/>
        /// where it is clear; the mask is a comparison's (all bits of a lane alike). One blend
        /// instruction with AVX: the JIT makes Vector.ConditionalSelect three (and, and-not, or)
        /// unless it can see that the mask came straight from a comparison.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Select(Vector<int> mask, Vector<float> a, Vector<float> b)
        {
            if (Avx.IsSupported && Vector<float>.Count == 8)
                return Avx.BlendVariable(b.AsVector256(), a.AsVector256(), mask.AsVector256().AsSingle()).AsVector();
            return Vector.ConditionalSelect(mask, a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Dot(in WideVector3 a, in WideVector3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static WideVector3 Cross(in WideVector3 a, in WideVector3 b) => new WideVector3
        {
            X = a.Y * b.Z - a.Z * b.Y,
            Y = a.Z * b.X - a.X * b.Z,
            Z = a.X * b.Y - a.Y * b.X,
        };

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static WideVector3 Scale(in WideVector3 a, Vector<float> s) => new WideVector3 { X = a.X * s, Y = a.Y * s, Z = a.Z * s };

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Add(in WideVector3 a)
        {
            X += a.X;
            Y += a.Y;
            Z += a.Z;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Subtract(in WideVector3 a)
        {
            X -= a.X;
            Y -= a.Y;
            Z -= a.Z;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void AddScaled(in WideVector3 a, Vector<float> s)
        {
            X += a.X * s;
            Y += a.Y * s;
            Z += a.Z * s;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SubtractScaled(in WideVector3 a, Vector<float> s)
        {
            X -= a.X * s;
            Y -= a.Y * s;
            Z -= a.Z * s;
        }

        /// <summary>Lane <paramref name="lane"/> of a wide float, by reference (for loading and storing lanes in place).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static ref float Lane(ref Vector<float> v, int lane) => ref Unsafe.Add(ref Unsafe.As<Vector<float>, float>(ref v), lane);

        /// <summary>Sets lane <paramref name="lane"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Set(int lane, Vector3 v)
        {
            Lane(ref X, lane) = v.X;
            Lane(ref Y, lane) = v.Y;
            Lane(ref Z, lane) = v.Z;
        }

        /// <summary>Lane <paramref name="lane"/>.</summary>
        public readonly Vector3 Get(int lane) => new Vector3(X.GetElement(lane), Y.GetElement(lane), Z.GetElement(lane));
    }
}
#endif
