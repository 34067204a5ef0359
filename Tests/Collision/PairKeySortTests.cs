using System;
using Fulcrum.Collision;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class PairKeySortTests
    {
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(23)]
        [TestCase(1000)]
        [TestCase(20000)]
        public void Sorts_keys_with_their_items_like_Array_Sort(int n)
        {
            var r = new Random(n + 7);
            for (int pattern = 0; pattern < 4; pattern++)
            {
                var keys = new ulong[n];
                var items = new int[n];
                for (int i = 0; i < n; i++)
                {
                    // Random, sorted with a few swaps (the usual step), reversed, many duplicates.
                    keys[i] = pattern switch
                    {
                        0 => ((ulong)(uint)r.Next() << 20) | (uint)r.Next(1 << 20),
                        1 => (ulong)i * 3,
                        2 => (ulong)(n - i),
                        _ => (ulong)r.Next(5),
                    };
                    items[i] = i;
                }
                if (pattern == 1)
                    for (int s = 0; s < n / 50; s++)
                    {
                        int a = r.Next(n), b = r.Next(n);
                        (keys[a], keys[b]) = (keys[b], keys[a]);
                        (items[a], items[b]) = (items[b], items[a]);
                    }
                var keyOfItem = new ulong[n];
                for (int i = 0; i < n; i++) keyOfItem[items[i]] = keys[i];
                PairKeySort.Sort(keys, items, n);
                for (int i = 1; i < n; i++) Assert.That(keys[i], Is.GreaterThanOrEqualTo(keys[i - 1]));
                for (int i = 0; i < n; i++) Assert.That(keyOfItem[items[i]], Is.EqualTo(keys[i]), "each item travelled with its key");
                var seen = new bool[n];
                foreach (int item in items) seen[item] = true;
                Assert.That(Array.TrueForAll(seen, x => x), Is.True, "a permutation");
            }
        }

        [Test]
        public void Key_order_reuses_last_order_only_for_the_same_arrivals()
        {
            var order = new KeyOrder();
            ulong[] keys = { 50, 10, 40, 20 };
            int[] items = { 5, 1, 4, 2 };
            order.Sort(keys, items, 4);
            Assert.That(items, Is.EqualTo(new[] { 1, 2, 4, 5 }));
            // The same arrivals again: the remembered order.
            keys = new ulong[] { 50, 10, 40, 20 };
            items = new[] { 5, 1, 4, 2 };
            order.Sort(keys, items, 4);
            Assert.That(items, Is.EqualTo(new[] { 1, 2, 4, 5 }));
            // The same keys for different items (a contact re-created in another slot): sorted afresh.
            keys = new ulong[] { 50, 10, 40, 20 };
            items = new[] { 7, 1, 4, 2 };
            order.Sort(keys, items, 4);
            Assert.That(items, Is.EqualTo(new[] { 1, 2, 4, 7 }));
            // A new key: sorted afresh.
            keys = new ulong[] { 50, 10, 30, 20 };
            items = new[] { 7, 1, 3, 2 };
            order.Sort(keys, items, 4);
            Assert.That(items, Is.EqualTo(new[] { 1, 2, 3, 7 }));
        }
    }
}
