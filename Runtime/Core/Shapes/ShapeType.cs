namespace Fulcrum
{
    /// <summary>
    /// The kinds of collision geometry. A compound is not a kind of its own: a body carries
    /// any number of shapes, each with its own local pose, which is what a compound is.
    /// </summary>
    public enum ShapeType : byte
    {
        /// <summary>A sphere about the shape origin.</summary>
        Sphere = 0,
        /// <summary>A box about the shape origin, given by half-extents.</summary>
        Box = 1,
        /// <summary>A capsule along the local y axis: radius and half-height of the inner segment.</summary>
        Capsule = 2,
        /// <summary>A convex hull of points.</summary>
        ConvexHull = 3,
        /// <summary>A half-space n . x &lt;= offset; static bodies only.</summary>
        Plane = 4,
        /// <summary>A triangle mesh; static bodies only.</summary>
        TriangleMesh = 5,
    }
}
