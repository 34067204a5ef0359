namespace Fulcrum.Collision
{
    internal sealed partial class PairMap
    {
        /// <summary>Writes the table as it is (slots, not just entries), so that it grows at the same moment after a restore.</summary>
        public void Save(StateWriter w)
        {
            w.Write(_count);
            w.WriteArray(_keys);
            w.WriteArray(_values);
        }

        /// <summary>Reads what <see cref="Save"/> wrote into a new map; values must be below <paramref name="valueLimit"/>.</summary>
        public static PairMap Load(StateReader r, int valueLimit)
        {
            var m = new PairMap();
            int count = r.Read<int>("pair map count");
            ulong[] keys = r.ReadArray<ulong>("pair map keys");
            int[] values = r.ReadArrayExactly<int>("pair map values", keys.Length);
            if (keys.Length < 64 || (keys.Length & (keys.Length - 1)) != 0 || count < 0 || 2 * count > keys.Length)
                throw r.Error($"the pair map has {keys.Length} slots for {count} pairs.");
            int live = 0;
            for (int i = 0; i < keys.Length; i++)
            {
                if (keys[i] == Empty) continue;
                live++;
                if ((uint)values[i] >= (uint)valueLimit) throw r.Error($"the pair map names contact {values[i]} of {valueLimit}.");
            }
            if (live != count) throw r.Error($"the pair map holds {live} pairs, {count} expected.");
            m._keys = keys;
            m._values = values;
            m._count = count;
            m._mask = keys.Length - 1;
            return m;
        }
    }
}
