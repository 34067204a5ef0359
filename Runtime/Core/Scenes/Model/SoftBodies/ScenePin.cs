using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// An entry of <c>pinned</c>: <c>{"min": [..], "max": [..], "to": "bodyName"}</c>. Vertices
    /// whose rest position (about the mesh centre) lies in the box are fixed in the world, or
    /// attached to the named body when <see cref="To"/> is given.
    /// </summary>
    public sealed class ScenePin
    {
        /// <summary><c>min</c>: the box's low corner in rest coordinates, m. Required.</summary>
        public Vector3 Min { get; set; }

        /// <summary><c>max</c>: the box's high corner, m, &gt;= min on every axis. Required.</summary>
        public Vector3 Max { get; set; }

        /// <summary><c>to</c>: the body the vertices follow; null: fixed in the world.</summary>
        public string? To { get; set; }
    }
}
