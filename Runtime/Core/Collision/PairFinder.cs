namespace Fulcrum.Collision
{
    /// <summary>
    /// Tree query callback of the broad phase: reports each overlapping shape to the world's
    /// pair filter, skipping overlaps another queued proxy will report.
    /// </summary>
    internal struct PairFinder : ITreeOverlapCallback
    {
        public const int TakeAll = 0;
        public const int SkipMovedBelow = 1;   // moving vs moving: the higher node reports
        public const int SkipMoved = 2;        // static vs moving: the moved moving proxy reports

        public World World;
        public DynamicAabbTree Tree;           // the tree being queried
        public int Shape;
        public int Node;
        public int Mode;

        public bool Visit(int proxyId, int userData)
        {
            if (userData == Shape) return true;
            if (Mode == SkipMovedBelow && proxyId < Node && Tree.WasMoved(proxyId)) return true;
            if (Mode == SkipMoved && Tree.WasMoved(proxyId)) return true;
            World.AddPair(Shape, userData);
            return true;
        }
    }
}
