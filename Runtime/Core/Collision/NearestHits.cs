using System;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The order of a cast's hits, and the nearest-first list an "all hits" cast keeps in the
    /// world's reusable buffer. Equal distances go by shape slot, so the order the tree visits
    /// shapes in never decides.
    /// </summary>
    internal static class NearestHits
    {
        /// <summary>Whether <paramref name="a"/> comes before <paramref name="b"/>: nearer, or as near and of a lower shape slot.</summary>
        public static bool Before<T>(in T a, in T b) where T : struct, IQueryHit =>
            a.Distance < b.Distance || (a.Distance == b.Distance && a.Shape.Index < b.Shape.Index);

        /// <summary>
        /// Counts <paramref name="hit"/> in <paramref name="found"/> and inserts it into the sorted
        /// prefix of <paramref name="hits"/> (the nearest <paramref name="capacity"/> so far),
        /// dropping the farthest once full.
        /// </summary>
        public static void Insert<T>(T[] hits, int capacity, ref int found, in T hit) where T : struct, IQueryHit
        {
            int kept = Math.Min(found, capacity);
            found++;
            int at = kept;
            while (at > 0 && Before(hit, hits[at - 1])) at--;
            if (at >= capacity) return;
            for (int i = Math.Min(kept, capacity - 1); i > at; i--) hits[i] = hits[i - 1];
            hits[at] = hit;
        }
    }
}
