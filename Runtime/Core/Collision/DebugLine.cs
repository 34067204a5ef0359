using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>A coloured line segment for debug drawing, world space.</summary>
    public struct DebugLine
    {
        /// <summary>Start, metres.</summary>
        public Vector3 A;
        /// <summary>End, metres.</summary>
        public Vector3 B;
        /// <summary>Colour as 0xAARRGGBB (see <see cref="DebugColor"/>).</summary>
        public uint Color;
    }
}
