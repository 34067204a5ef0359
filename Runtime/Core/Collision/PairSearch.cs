using System;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The broad phase's pair search on the worker pool (after Box2D v3's parallel pair
    /// finding): the queued proxies are split into contiguous blocks; each block walks the
    /// trees for its proxies (<see cref="BroadPhase.FindPairs{T}"/>) and keeps the pairs the
    /// callback accepts in a buffer of its own. The stepping thread then hands the pairs to
    /// <see cref="IPairCallback.AddPair"/> block by block, which is the serial search's order,
    /// so contacts are created exactly as without threads. A block whose buffer fills stops at
    /// the proxy that overflowed it; the stepping thread searches the rest of that block itself
    /// and the buffer doubles for the next step (only there, so the workers never allocate).
    /// </summary>
    internal sealed class PairSearch<T> : IParallelJob where T : struct, IPairCallback
    {
        /// <summary>Fewer queued proxies than this are searched on the stepping thread.</summary>
        public const int MinMoved = 64;

        /// <summary>Searches run on the pool, and blocks that filled their buffer (for tests).</summary>
        public long Runs, Overflows;

        BroadPhase? _broadPhase;
        T _callback;
        int _moved, _blocks;
        int[][] _pairs = Array.Empty<int[]>();
        int[] _count = Array.Empty<int>();
        // Per block: the queued proxy its search stopped at (the block's end when it finished).
        int[] _stop = Array.Empty<int>();

        /// <summary>Sizes the buffers for <paramref name="pairs"/> new pairs in one step on <paramref name="threads"/> threads.</summary>
        public void Reserve(int pairs, int threads)
        {
            EnsureBlocks(BlocksFor(int.MaxValue, threads));
            // The queued proxies are spread over the blocks; twice an even share leaves room for
            // uneven blocks, and a block that still fills only costs its rest on one thread.
            int each = Math.Max(MinCapacity, 2 * pairs / Math.Max(1, _pairs.Length));
            for (int b = 0; b < _pairs.Length; b++)
                if (_pairs[b].Length < 2 * each) _pairs[b] = new int[2 * each];
        }

        const int MinCapacity = 64;

        // A few blocks per thread balance crowded proxies against lonely ones.
        static int BlocksFor(int moved, int threads) => Math.Max(1, Math.Min(moved / 16, 4 * threads));

        void EnsureBlocks(int blocks)
        {
            if (_pairs.Length >= blocks) return;
            int old = _pairs.Length;
            Array.Resize(ref _pairs, blocks);
            Array.Resize(ref _count, blocks);
            Array.Resize(ref _stop, blocks);
            for (int b = old; b < blocks; b++) _pairs[b] = new int[2 * MinCapacity];
        }

        int From(int b) => (int)((long)_moved * b / _blocks);

        /// <summary>
        /// Searches the pairs of queued proxies [0, <paramref name="moved"/>) of
        /// <paramref name="broadPhase"/> on <paramref name="pool"/> and hands the accepted ones
        /// to <paramref name="callback"/> in the serial search's order.
        /// </summary>
        public void Run(BroadPhase broadPhase, ref T callback, int moved, IParallelScheduler pool)
        {
            _broadPhase = broadPhase;
            _callback = callback;
            _moved = moved;
            _blocks = BlocksFor(moved, pool.ThreadCount);
            EnsureBlocks(_blocks);
            pool.For(this, 0, _blocks, 1);
            Runs++;
            for (int b = 0; b < _blocks; b++)
            {
                int[] pairs = _pairs[b];
                for (int p = 0; p < _count[b]; p++) callback.AddPair(pairs[2 * p], pairs[2 * p + 1]);
                int end = From(b + 1);
                if (_stop[b] == end) continue;
                for (int i = _stop[b]; i < end; i++) broadPhase.FindPairs(i, ref callback);
                _pairs[b] = new int[2 * pairs.Length];
                Overflows++;
            }
            _broadPhase = null;
            _callback = default;
        }

        /// <summary>Searches blocks [<paramref name="start"/>, <paramref name="end"/>) (on a worker).</summary>
        public void Execute(int start, int end)
        {
            for (int b = start; b < end; b++)
            {
                var collector = new Collector { Callback = _callback, Pairs = _pairs[b] };
                int from = From(b), to = From(b + 1);
                int i = from;
                for (; i < to; i++)
                {
                    int mark = collector.Count;
                    _broadPhase!.FindPairs(i, ref collector);
                    if (collector.Full)
                    {
                        collector.Count = mark;
                        break;
                    }
                }
                _count[b] = collector.Count;
                _stop[b] = i;
            }
        }

        // Keeps the accepted pairs of one block; past its buffer's end it only notes that it
        // was full (the stepping thread then searches that proxy again).
        struct Collector : IPairCallback
        {
            public T Callback;
            public int[] Pairs;
            public int Count;
            public bool Full;

            public bool Accepts(int shapeA, int shapeB) => !Full && Callback.Accepts(shapeA, shapeB);

            public void AddPair(int shapeA, int shapeB)
            {
                if (2 * Count + 1 >= Pairs.Length)
                {
                    Full = true;
                    return;
                }
                Pairs[2 * Count] = shapeA;
                Pairs[2 * Count + 1] = shapeB;
                Count++;
            }
        }
    }
}
