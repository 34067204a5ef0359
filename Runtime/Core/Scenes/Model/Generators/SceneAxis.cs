using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// The horizontal direction a row-like generator runs along (JSON <c>"x"</c> or <c>"z"</c>).
    /// Such generators give <c>size</c> in their own frame: [along, up, across].
    /// </summary>
    public enum SceneAxis : byte
    {
        /// <summary>Along world +x; across is z.</summary>
        X = 0,
        /// <summary>Along world +z; across is x.</summary>
        Z = 1,
    }

    /// <summary>Maps a generator's [along, up, across] frame to world axes.</summary>
    public static class SceneAxisFrame
    {
        /// <summary>The world unit vector along <paramref name="axis"/>.</summary>
        public static Vector3 Along(SceneAxis axis) => axis == SceneAxis.X ? Vector3.UnitX : Vector3.UnitZ;

        /// <summary>The world unit vector across <paramref name="axis"/> (horizontal, perpendicular).</summary>
        public static Vector3 Across(SceneAxis axis) => axis == SceneAxis.X ? Vector3.UnitZ : Vector3.UnitX;

        /// <summary>A size given as [along, up, across] in world axes.</summary>
        public static Vector3 ToWorld(SceneAxis axis, Vector3 size) =>
            axis == SceneAxis.X ? size : new Vector3(size.Z, size.Y, size.X);
    }
}
