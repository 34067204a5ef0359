namespace Fulcrum.Collision
{
    /// <summary>
    /// Sorts pair keys with their items in place, without allocating: Array.Sort's generic
    /// key/item path creates its comparer helper lazily, through reflection, the first time it
    /// meets a type pair, and that can land inside a step. Keys arrive nearly sorted (the
    /// contact list keeps its order between steps), which insertion sort finishes in one pass;
    /// a quicksort with median-of-three pivots cuts longer runs down to that size first.
    /// </summary>
    internal static class PairKeySort
    {
        const int InsertionLimit = 24;

        /// <summary>Sorts keys[0, n) ascending, moving items[0, n) with them.</summary>
        public static void Sort(ulong[] keys, int[] items, int n)
        {
            QuickSort(keys, items, 0, n - 1);
            InsertionSort(keys, items, n);
        }

        // Leaves every range shorter than InsertionLimit unsorted for the final insertion pass.
        static void QuickSort(ulong[] keys, int[] items, int lo, int hi)
        {
            while (hi - lo >= InsertionLimit)
            {
                int mid = lo + ((hi - lo) >> 1);
                if (keys[mid] < keys[lo]) Swap(keys, items, mid, lo);
                if (keys[hi] < keys[lo]) Swap(keys, items, hi, lo);
                if (keys[hi] < keys[mid]) Swap(keys, items, hi, mid);
                ulong pivot = keys[mid];
                int i = lo, j = hi;
                while (i <= j)
                {
                    while (keys[i] < pivot) i++;
                    while (keys[j] > pivot) j--;
                    if (i <= j) Swap(keys, items, i++, j--);
                }
                // Recurse into the smaller side, loop on the larger: stack depth stays O(log n).
                if (j - lo < hi - i)
                {
                    QuickSort(keys, items, lo, j);
                    lo = i;
                }
                else
                {
                    QuickSort(keys, items, i, hi);
                    hi = j;
                }
            }
        }

        static void InsertionSort(ulong[] keys, int[] items, int n)
        {
            for (int i = 1; i < n; i++)
            {
                ulong key = keys[i];
                int item = items[i];
                int j = i - 1;
                while (j >= 0 && keys[j] > key)
                {
                    keys[j + 1] = keys[j];
                    items[j + 1] = items[j];
                    j--;
                }
                keys[j + 1] = key;
                items[j + 1] = item;
            }
        }

        static void Swap(ulong[] keys, int[] items, int a, int b)
        {
            (keys[a], keys[b]) = (keys[b], keys[a]);
            (items[a], items[b]) = (items[b], items[a]);
        }
    }
}
