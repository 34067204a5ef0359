namespace Fulcrum.Collision
{
    /// <summary>
    /// Tree query callback of the broad phase: reports each overlapping shape to the pair
    /// callback <typeparamref name="T"/>, skipping overlaps another queued proxy will report.
    /// </summary>
    internal struct PairFinder<T> : ITreeOverlapCallback where T : struct, IPairCallback
    {
        public T Callback;                     // copied in and out by BroadPhase.UpdatePairs
        public DynamicAabbTree Tree;           // the tree being queried
        public int Shape;
        public int Node;
        public int Mode;

        public bool Visit(int proxyId, int userData)
        {
            if (userData == Shape) return true;
            if (Mode == PairFinderMode.SkipMovedBelow && proxyId < Node && Tree.WasMoved(proxyId)) return true;
            if (Mode == PairFinderMode.SkipMoved && Tree.WasMoved(proxyId)) return true;
            if (Callback.Accepts(Shape, userData)) Callback.AddPair(Shape, userData);
            return true;
        }
    }

    /// <summary>Which overlaps a <see cref="PairFinder{T}"/> leaves to another queued proxy.</summary>
    internal static class PairFinderMode
    {
        public const int TakeAll = 0;
        public const int SkipMovedBelow = 1;   // moving vs moving: the higher node reports
        public const int SkipMoved = 2;        // static vs moving: the moved moving proxy reports
    }
}
