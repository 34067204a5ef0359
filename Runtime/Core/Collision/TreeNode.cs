using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A node of a <see cref="DynamicAabbTree"/> (48 bytes). Leaves hold one proxy; internal
    /// nodes always have two children. A free node has <see cref="Height"/> -1 and links the
    /// free list through <see cref="Parent"/>.
    /// </summary>
    internal struct TreeNode
    {
        public Aabb Box;        // fat bounds (leaves) or the union of the children
        public int Parent;      // -1 at the root; next free node when free
        public int Child1;      // -1 for a leaf
        public int Child2;
        public int Height;      // 0 for a leaf, -1 when free
        public int UserData;    // shape slot (leaves)
        public bool Moved;      // leaf moved this step: pair finding skips duplicate queries

        public readonly bool IsLeaf => Child1 < 0;
    }
}
