using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "mesh", "vertices": [[x, y, z], ...], "triangles": [[i, j, k], ...]}</c>:
    /// a triangle mesh, static bodies only. Triangles index <see cref="Vertices"/> from 0;
    /// counter-clockwise seen from the front.
    /// </summary>
    public sealed class SceneMesh : SceneShape
    {
        /// <inheritdoc/>
        public override SceneShapeType Type => SceneShapeType.Mesh;

        /// <summary><c>vertices</c> in the shape frame, m. Required, at least 3.</summary>
        public List<Vector3> Vertices { get; } = new List<Vector3>();

        /// <summary><c>triangles</c> flattened: three vertex indices per triangle. Required, at least one triangle.</summary>
        public List<int> Triangles { get; } = new List<int>();
    }
}
