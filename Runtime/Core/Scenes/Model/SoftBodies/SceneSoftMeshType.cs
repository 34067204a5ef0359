namespace Fulcrum.Scenes
{
    /// <summary>The <c>type</c> of a soft body's <c>mesh</c>.</summary>
    public enum SceneSoftMeshType : byte
    {
        /// <summary><c>box{size, cells}</c>: a box of <c>size</c> split into cells x, y, z (each cell into tetrahedra).</summary>
        Box = 0,
    }
}
