using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Greedy graph colouring of elements: two elements that share a vertex never get the same
    /// colour, so all elements of one colour can be projected at once (on any number of
    /// threads) with exactly the result of doing them one after another. Colours are then
    /// laid out contiguously, so a colour is an index range.
    /// </summary>
    internal static class ElementColoring
    {
        /// <summary>
        /// Colours the elements of a flat index list (<paramref name="arity"/> vertices each).
        /// Returns the new order (position -> original element) and, in <paramref name="colorStart"/>,
        /// the first position of each colour plus one past the end.
        /// </summary>
        public static int[] Color(ReadOnlySpan<int> indices, int arity, int vertexCount, out int[] colorStart)
        {
            int count = indices.Length / arity;
            var valence = new int[vertexCount];
            foreach (int v in indices) valence[v]++;
            int maxValence = 0;
            foreach (int n in valence) maxValence = Math.Max(maxValence, n);
            // An element sees at most arity * (maxValence - 1) neighbours, so this many colours suffice.
            int words = (arity * Math.Max(maxValence - 1, 0) + 1 + 63) / 64;
            var used = new ulong[vertexCount * words];
            var color = new int[count];
            int colors = 0;
            for (int e = 0; e < count; e++)
            {
                int c = 0;
                for (int w = 0; w < words; w++)
                {
                    ulong taken = 0;
                    for (int q = 0; q < arity; q++) taken |= used[indices[e * arity + q] * words + w];
                    if (taken != ulong.MaxValue)
                    {
                        c = w * 64 + TrailingOnes(taken);
                        break;
                    }
                }
                color[e] = c;
                colors = Math.Max(colors, c + 1);
                for (int q = 0; q < arity; q++) used[indices[e * arity + q] * words + c / 64] |= 1UL << (c % 64);
            }
            colorStart = new int[colors + 1];
            foreach (int c in color) colorStart[c + 1]++;
            for (int c = 0; c < colors; c++) colorStart[c + 1] += colorStart[c];
            var order = new int[count];
            var fill = (int[])colorStart.Clone();
            for (int e = 0; e < count; e++) order[fill[color[e]]++] = e;
            return order;
        }

        static int TrailingOnes(ulong x)
        {
            int n = 0;
            while ((x & 1) != 0)
            {
                x >>= 1;
                n++;
            }
            return n;
        }
    }
}
