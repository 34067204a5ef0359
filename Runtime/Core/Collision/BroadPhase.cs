using System;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Two dynamic AABB trees, one for static shapes and one for kinematic and dynamic ones,
    /// and the buffer of proxies that moved (or were created) since the last pair search.
    /// A proxy key is <c>2 * node + 1</c> in the moving tree and <c>2 * node</c> in the static
    /// one. Only moved proxies look for new pairs, so a resting pile costs nothing here;
    /// pairs end in the narrow phase when their fat boxes stop overlapping.
    /// </summary>
    internal sealed partial class BroadPhase
    {
        public readonly DynamicAabbTree StaticTree = new DynamicAabbTree();
        public readonly DynamicAabbTree MovingTree = new DynamicAabbTree();
        int[] _moved = new int[64];
        int _movedCount;

        /// <summary>Proxies waiting for a pair search.</summary>
        public int MovedCount => _movedCount;

        public static bool IsMoving(int key) => (key & 1) != 0;

        public static int Node(int key) => key >> 1;

        public DynamicAabbTree TreeOf(int key) => (key & 1) != 0 ? MovingTree : StaticTree;

        /// <summary>The fat box of a proxy.</summary>
        public ref readonly Aabb FatAabb(int key) => ref TreeOf(key).FatAabb(key >> 1);

        /// <summary>Adds a shape's proxy; it looks for pairs at the next update.</summary>
        public int CreateProxy(in Aabb fatBox, int shape, bool isStatic)
        {
            DynamicAabbTree tree = isStatic ? StaticTree : MovingTree;
            int key = 2 * tree.CreateProxy(fatBox, shape) + (isStatic ? 0 : 1);
            Buffer(key);
            return key;
        }

        /// <summary>Removes a proxy (and forgets it in the move buffer).</summary>
        public void DestroyProxy(int key)
        {
            DynamicAabbTree tree = TreeOf(key);
            if (tree.WasMoved(key >> 1))
                for (int i = 0; i < _movedCount; i++)
                    if (_moved[i] == key) _moved[i] = -1;
            tree.DestroyProxy(key >> 1);
        }

        /// <summary>Sizes the queue of moved proxies for <paramref name="proxies"/> proxies.</summary>
        public void Reserve(int proxies)
        {
            if (_moved.Length < proxies) Array.Resize(ref _moved, proxies);
        }

        /// <summary>Gives a proxy a new fat box and queues it for a pair search.</summary>
        public void MoveProxy(int key, in Aabb fatBox)
        {
            DynamicAabbTree tree = TreeOf(key);
            tree.MoveProxy(key >> 1, fatBox);
            if (!tree.WasMoved(key >> 1)) Buffer(key);
        }

        /// <summary>Queues a proxy for a pair search without moving it (a pair the filter refused may now be accepted).</summary>
        public void Requeue(int key)
        {
            if (!TreeOf(key).WasMoved(key >> 1)) Buffer(key);
        }

        void Buffer(int key)
        {
            TreeOf(key).SetMoved(key >> 1, true);
            if (_movedCount == _moved.Length) Array.Resize(ref _moved, 2 * _moved.Length);
            _moved[_movedCount++] = key;
        }

        /// <summary>
        /// Finds the new overlaps of every queued proxy and hands each pair of shapes that
        /// <paramref name="callback"/> accepts to it once (a pair of two moved proxies is reported
        /// by the one with the higher node; a moved static proxy leaves moved moving proxies to
        /// report it). With a <paramref name="search"/> and a <paramref name="pool"/>, and enough
        /// queued proxies, the tree queries and the accept tests run on the pool first; the
        /// pairs reach <see cref="IPairCallback.AddPair"/> in the same order either way.
        /// </summary>
        public void UpdatePairs<T>(ref T callback, PairSearch<T>? search = null, IParallelScheduler? pool = null) where T : struct, IPairCallback
        {
            if (search != null && pool != null && _movedCount >= PairSearch<T>.MinMoved)
                search.Run(this, ref callback, _movedCount, pool);
            else
                for (int i = 0; i < _movedCount; i++) FindPairs(i, ref callback);
            for (int i = 0; i < _movedCount; i++)
                if (_moved[i] >= 0) TreeOf(_moved[i]).SetMoved(_moved[i] >> 1, false);
            _movedCount = 0;
        }

        /// <summary>
        /// The new overlaps of queued proxy <paramref name="i"/>, accepted pairs handed to
        /// <paramref name="callback"/> in the order the trees are walked. Reads the trees only.
        /// </summary>
        public void FindPairs<T>(int i, ref T callback) where T : struct, IPairCallback
        {
            int key = _moved[i];
            if (key < 0) return;
            DynamicAabbTree tree = TreeOf(key);
            int node = key >> 1;
            Aabb box = tree.FatAabb(node);
            var finder = new PairFinder<T> { Callback = callback, Shape = tree.UserData(node), Node = node, Tree = MovingTree };
            if (IsMoving(key))
            {
                finder.Mode = PairFinderMode.SkipMovedBelow;
                MovingTree.Query(box, ref finder);
                finder.Tree = StaticTree;
                finder.Mode = PairFinderMode.TakeAll;
                StaticTree.Query(box, ref finder);
            }
            else
            {
                finder.Mode = PairFinderMode.SkipMoved;
                MovingTree.Query(box, ref finder);
            }
            callback = finder.Callback;
        }
    }
}
