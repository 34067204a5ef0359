using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>One entry of a compound's <c>children</c>.</summary>
    public sealed class SceneCompoundChild
    {
        /// <summary><c>shape</c>. Required.</summary>
        public SceneShape? Shape { get; set; }

        /// <summary><c>position</c> in the body frame, m. Default: 0.</summary>
        public Vector3 Position { get; set; }

        /// <summary><c>rotation</c> in the body frame, quaternion <c>[x, y, z, w]</c>. Default: identity.</summary>
        public Quaternion Rotation { get; set; } = Quaternion.Identity;
    }
}
