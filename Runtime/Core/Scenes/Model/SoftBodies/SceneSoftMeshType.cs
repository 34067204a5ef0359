namespace Fulcrum.Scenes
{
    /// <summary>The <c>type</c> of a soft body's <c>mesh</c>.</summary>
    public enum SceneSoftMeshType : byte
    {
        /// <summary><c>box{size, cells}</c>: a box of <c>size</c> split into cells x, y, z (each cell into tetrahedra).</summary>
        Box = 0,
        /// <summary><c>sphere{radius, cells}</c>: a ball carved from a grid of <c>cells</c> along its diameter.</summary>
        Sphere = 1,
        /// <summary><c>capsule{radius, halfHeight, cells}</c>: a capsule along y carved from a grid of <c>cells</c> across.</summary>
        Capsule = 2,
        /// <summary><c>beam{length, thickness, cells}</c>: a square bar along x, <c>cells</c> along its length.</summary>
        Beam = 3,
        /// <summary><c>cloth{size, cells, thickness, bendingScale}</c>: a rectangular triangle shell in the x-z plane.</summary>
        Cloth = 4,
        /// <summary><c>tetgen{node, ele}</c>: tetrahedra read from a TetGen .node/.ele file pair.</summary>
        TetGen = 5,
        /// <summary><c>obj{file, thickness, bendingScale}</c>: a triangle shell read from a Wavefront OBJ file.</summary>
        Obj = 6,
        /// <summary><c>surface{file, resolution}</c>: a closed triangle surface read from a Wavefront OBJ file and tetrahedralised.</summary>
        Surface = 7,
    }
}
