namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "obj", "file": "sail.obj", "thickness": t, "bendingScale": b}</c>: a triangle
    /// shell read from a Wavefront OBJ file (v and f statements). The path is relative to the
    /// scene file's folder (or absolute); the file is read when the soft body is built.
    /// </summary>
    public sealed class SceneSoftObj : SceneSoftMesh
    {
        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.Obj;

        /// <summary><c>file</c>: path of the .obj file. Required.</summary>
        public string File { get; set; } = "";

        /// <summary><c>thickness</c> of the sheet, m, &gt; 0. Default: 0.0005.</summary>
        public float Thickness { get; set; } = SceneSoftCloth.DefaultThickness;

        /// <summary><c>bendingScale</c>: multiplies the physical bending rigidity, &gt;= 0. Default: 1.</summary>
        public float BendingScale { get; set; } = 1f;
    }
}
