using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A node of a static <see cref="TriangleBvh"/> (32 bytes). A leaf holds
    /// <see cref="Count"/> &gt; 0 triangles starting at <see cref="Start"/> in the BVH's
    /// triangle order; an internal node has Count 0, its left child next to it and its right
    /// child at <see cref="Start"/>.
    /// </summary>
    internal struct BvhNode
    {
        public Aabb Box;
        public int Start;
        public int Count;
    }
}
