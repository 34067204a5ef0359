#if NET
using System.Runtime.CompilerServices;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>Vector&lt;float&gt;.Count 3x3 matrices side by side, by columns (as <see cref="Mat3"/>).</summary>
    internal struct WideMatrix3
    {
        public WideVector3 C0, C1, C2;

        /// <summary>M v.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly WideVector3 Transform(in WideVector3 v) => new WideVector3
        {
            X = C0.X * v.X + C1.X * v.Y + C2.X * v.Z,
            Y = C0.Y * v.X + C1.Y * v.Y + C2.Y * v.Z,
            Z = C0.Z * v.X + C1.Z * v.Y + C2.Z * v.Z,
        };

        /// <summary>Sets lane <paramref name="lane"/>.</summary>
        public void Set(int lane, in Mat3 m)
        {
            C0.Set(lane, m.C0);
            C1.Set(lane, m.C1);
            C2.Set(lane, m.C2);
        }
    }
}
#endif
