using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary><c>{"type": "convex", "points": [[x, y, z], ...]}</c>: the convex hull of at least 4 points.</summary>
    public sealed class SceneConvex : SceneShape
    {
        /// <inheritdoc/>
        public override SceneShapeType Type => SceneShapeType.Convex;

        /// <summary><c>points</c> in the shape frame, m. Required, at least 4.</summary>
        public List<Vector3> Points { get; } = new List<Vector3>();
    }
}
