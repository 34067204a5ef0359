namespace Fulcrum.Scenes
{
    /// <summary>The <c>type</c> of a scene shape (the JSON name is the lower-case one).</summary>
    public enum SceneShapeType : byte
    {
        /// <summary><c>sphere{radius}</c>.</summary>
        Sphere = 0,
        /// <summary><c>box{halfExtents}</c>.</summary>
        Box = 1,
        /// <summary><c>capsule{radius, halfHeight}</c>, axis y.</summary>
        Capsule = 2,
        /// <summary><c>convex{points}</c>: the convex hull of the points.</summary>
        Convex = 3,
        /// <summary><c>plane{normal, offset}</c>: static bodies only.</summary>
        Plane = 4,
        /// <summary><c>mesh{vertices, triangles}</c>: static bodies only.</summary>
        Mesh = 5,
        /// <summary><c>compound{children}</c>: several shapes on one body.</summary>
        Compound = 6,
    }
}
