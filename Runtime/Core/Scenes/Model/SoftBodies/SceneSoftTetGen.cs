namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "tetgen", "node": "ball.node", "ele": "ball.ele"}</c>: tetrahedra read from a
    /// TetGen file pair. Paths are relative to the scene file's folder (or absolute); the files
    /// are read when the soft body is built, not when the scene is parsed.
    /// </summary>
    public sealed class SceneSoftTetGen : SceneSoftMesh
    {
        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.TetGen;

        /// <summary><c>node</c>: path of the .node file (vertices). Required.</summary>
        public string Node { get; set; } = "";

        /// <summary><c>ele</c>: path of the .ele file (tetrahedra). Required.</summary>
        public string Ele { get; set; } = "";
    }
}
