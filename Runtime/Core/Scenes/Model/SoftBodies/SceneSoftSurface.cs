namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "surface", "file": "bunny.obj", "resolution": n}</c>: a closed triangle surface
    /// read from a Wavefront OBJ file (v and f statements) and filled with tetrahedra carved from a
    /// cubic grid of <c>resolution</c> cells along the surface's longest side. The path is relative
    /// to the scene file's folder (or absolute); the file is read when the soft body is built.
    /// </summary>
    public sealed class SceneSoftSurface : SceneSoftMesh
    {
        /// <summary>Smallest accepted <see cref="Resolution"/>.</summary>
        public const int MinResolution = 2;

        /// <summary>Largest accepted <see cref="Resolution"/> (the carve is O(grid vertices x triangles)).</summary>
        public const int MaxResolution = 64;

        /// <inheritdoc/>
        public override SceneSoftMeshType Type => SceneSoftMeshType.Surface;

        /// <summary><c>file</c>: path of the .obj file. Required.</summary>
        public string File { get; set; } = "";

        /// <summary><c>resolution</c>: grid cells along the longest side, in [2, 64]. Default: 8.</summary>
        public int Resolution { get; set; } = 8;
    }
}
