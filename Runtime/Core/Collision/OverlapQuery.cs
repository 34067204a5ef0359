using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Tree callback of the world's overlap query: runs the pair function of the query shape
    /// against each candidate with no speculative margin; touching or overlapping shapes are
    /// collected in the world's reusable slot list.
    /// </summary>
    internal struct OverlapQuery : ITreeOverlapCallback
    {
        public World World;
        public QueryFilter Filter;
        public ShapeGeometry Shape;
        public Pose Pose;
        public ContactBuffer Buffer;
        public int[] Found;
        public int Count;

        public bool Visit(int proxyId, int shape)
        {
            if (!World.PassesFilter(shape, Filter)) return true;
            Buffer.Clear(0);
            CollisionTable.Collide(Shape, Pose, World.Shapes.Geometry[shape], World.ShapeWorldPose(shape), Buffer);
            if (Buffer.PointCount == 0) return true;
            if (Count == Found.Length) System.Array.Resize(ref Found, 2 * Found.Length);
            Found[Count++] = shape;
            return true;
        }
    }
}
