namespace Fulcrum.Collision
{
    /// <summary>The core of a convex shape as GJK sees it (the radius is added afterwards).</summary>
    internal enum SupportKind : byte
    {
        Point = 0,      // sphere core
        Segment = 1,    // capsule core
        Box = 2,
        Polytope = 3,   // convex hull vertices
        Triangle = 4,   // one mesh triangle
    }
}
