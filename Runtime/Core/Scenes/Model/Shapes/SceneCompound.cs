using System.Collections.Generic;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "compound", "children": [{"shape": ..., "position": ..., "rotation": ...}]}</c>:
    /// several shapes on one body, each at its pose in the body frame. Children are sphere,
    /// box, capsule or convex shapes (no planes, meshes or nested compounds).
    /// </summary>
    public sealed class SceneCompound : SceneShape
    {
        /// <inheritdoc/>
        public override SceneShapeType Type => SceneShapeType.Compound;

        /// <summary><c>children</c>. Required, at least one.</summary>
        public List<SceneCompoundChild> Children { get; } = new List<SceneCompoundChild>();
    }
}
