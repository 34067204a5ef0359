using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>A coloured point for debug drawing, world space.</summary>
    public struct DebugPoint
    {
        /// <summary>Position, metres.</summary>
        public Vector3 Position;
        /// <summary>Suggested size on screen, metres (a renderer may ignore it).</summary>
        public float Size;
        /// <summary>Colour as 0xAARRGGBB (see <see cref="DebugColor"/>).</summary>
        public uint Color;
    }
}
