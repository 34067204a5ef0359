using System;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Puts items in the order of their pair keys, remembering the answer: when the same items
    /// arrive with the same keys in the same order as last time (a step in which no contact
    /// began or ended), last time's order is copied instead of sorting again. Grows only when
    /// more items arrive than ever before.
    /// </summary>
    internal sealed class KeyOrder
    {
        ulong[] _keys = new ulong[64];
        int[] _arrived = new int[64];
        int[] _sorted = new int[64];
        int _count = -1;

        /// <summary>Sizes the remembered order for <paramref name="n"/> items.</summary>
        public void Reserve(int n)
        {
            if (_keys.Length >= n) return;
            _keys = new ulong[n];
            _arrived = new int[n];
            _sorted = new int[n];
            _count = -1;
        }

        /// <summary>
        /// Reorders items[0, n) by keys[0, n) ascending. Keys are sorted too when a sort runs,
        /// and left in arrival order when the remembered order is reused.
        /// </summary>
        public void Sort(ulong[] keys, int[] items, int n)
        {
            if (n == _count && Same(keys, items, n))
            {
                Array.Copy(_sorted, items, n);
                return;
            }
            if (_keys.Length < n)
            {
                int size = Math.Max(n, 2 * _keys.Length);
                _keys = new ulong[size];
                _arrived = new int[size];
                _sorted = new int[size];
            }
            Array.Copy(keys, _keys, n);
            Array.Copy(items, _arrived, n);
            if (n > 1 && !IsSorted(keys, n)) PairKeySort.Sort(keys, items, n);
            Array.Copy(items, _sorted, n);
            _count = n;
        }

        bool Same(ulong[] keys, int[] items, int n) =>
            new ReadOnlySpan<ulong>(keys, 0, n).SequenceEqual(new ReadOnlySpan<ulong>(_keys, 0, n)) &&
            new ReadOnlySpan<int>(items, 0, n).SequenceEqual(new ReadOnlySpan<int>(_arrived, 0, n));

        static bool IsSorted(ulong[] keys, int n)
        {
            for (int k = 1; k < n; k++)
                if (keys[k] < keys[k - 1]) return false;
            return true;
        }
    }
}
