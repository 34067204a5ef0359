using System;

namespace Fulcrum.Collision
{
    /// <summary>
    /// An open-addressing hash map from a shape-pair key to a contact id: linear probing,
    /// load kept at or below one half, deletion by backward shifting (no tombstones), so
    /// lookups stay short however many pairs come and go. Grows by doubling, amortised.
    /// </summary>
    internal sealed partial class PairMap
    {
        const ulong Empty = ulong.MaxValue;
        ulong[] _keys;
        int[] _values;
        int _count;
        int _mask;

        public PairMap()
        {
            _keys = new ulong[64];
            _values = new int[64];
            _mask = 63;
            _keys.AsSpan().Fill(Empty);
        }

        /// <summary>Entries in the map.</summary>
        public int Count => _count;

        /// <summary>The key of an unordered shape pair: the smaller slot in the high half.</summary>
        public static ulong Key(int shapeA, int shapeB) => shapeA < shapeB
            ? ((ulong)(uint)shapeA << 32) | (uint)shapeB
            : ((ulong)(uint)shapeB << 32) | (uint)shapeA;

        // Fibonacci hashing: the golden-ratio multiply spreads consecutive slot pairs.
        int Home(ulong key) => (int)((key * 0x9E3779B97F4A7C15UL) >> 40) & _mask;

        /// <summary>The value stored for the key, or -1.</summary>
        public int Find(ulong key)
        {
            int i = Home(key);
            while (true)
            {
                ulong k = _keys[i];
                if (k == key) return _values[i];
                if (k == Empty) return -1;
                i = (i + 1) & _mask;
            }
        }

        /// <summary>Adds a key that is not present.</summary>
        public void Add(ulong key, int value)
        {
            if (2 * (_count + 1) > _keys.Length) Grow();
            int i = Home(key);
            while (_keys[i] != Empty) i = (i + 1) & _mask;
            _keys[i] = key;
            _values[i] = value;
            _count++;
        }

        /// <summary>Removes a key; false when it was not present.</summary>
        public bool Remove(ulong key)
        {
            int i = Home(key);
            while (true)
            {
                ulong k = _keys[i];
                if (k == Empty) return false;
                if (k == key) break;
                i = (i + 1) & _mask;
            }
            // Backward shift: move later entries of the probe run into the hole when their
            // home position does not lie cyclically in (hole, their slot].
            int hole = i;
            int j = i;
            while (true)
            {
                j = (j + 1) & _mask;
                ulong k = _keys[j];
                if (k == Empty) break;
                int home = Home(k);
                bool stays = hole <= j ? (hole < home && home <= j) : (hole < home || home <= j);
                if (stays) continue;
                _keys[hole] = k;
                _values[hole] = _values[j];
                hole = j;
            }
            _keys[hole] = Empty;
            _count--;
            return true;
        }

        /// <summary>Grows the table so that <paramref name="pairs"/> pairs fit without growing again.</summary>
        public void Reserve(int pairs)
        {
            while (2 * pairs > _keys.Length) Grow();
        }

        void Grow()
        {
            ulong[] oldKeys = _keys;
            int[] oldValues = _values;
            _keys = new ulong[oldKeys.Length * 2];
            _values = new int[oldKeys.Length * 2];
            _keys.AsSpan().Fill(Empty);
            _mask = _keys.Length - 1;
            _count = 0;
            for (int i = 0; i < oldKeys.Length; i++)
                if (oldKeys[i] != Empty) Add(oldKeys[i], oldValues[i]);
        }
    }
}
