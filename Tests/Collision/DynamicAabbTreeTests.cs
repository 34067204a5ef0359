using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;
using NUnit.Framework;

namespace Fulcrum.Tests.Collision
{
    public class DynamicAabbTreeTests
    {
        struct Collect : ITreeOverlapCallback
        {
            public List<int> Found;
            public bool Visit(int proxyId, int userData) { Found.Add(userData); return true; }
        }

        struct RayCollect : ITreeRayCallback
        {
            public List<int> Found;
            public float Visit(int proxyId, int userData, float maxFraction) { Found.Add(userData); return maxFraction; }
        }

        static Aabb RandomBox(Random r, float world)
        {
            Vector3 c = CollisionTestKit.RandomVector(r, world);
            Vector3 e = new Vector3(0.1f + (float)r.NextDouble(), 0.1f + (float)r.NextDouble(), 0.1f + (float)r.NextDouble());
            return Aabb.FromCenterExtents(c, e);
        }

        [Test]
        public void Random_inserts_moves_and_removes_keep_every_invariant_and_queries_match_brute_force()
        {
            var r = new Random(7);
            var tree = new DynamicAabbTree();
            var boxes = new Dictionary<int, (int proxy, Aabb box)>();
            int nextUser = 0;
            for (int op = 0; op < 4000; op++)
            {
                int kind = r.Next(10);
                if (kind < 4 || boxes.Count < 10)
                {
                    Aabb b = RandomBox(r, 30);
                    boxes[nextUser] = (tree.CreateProxy(b, nextUser), b);
                    nextUser++;
                }
                else if (kind < 8)
                {
                    int key = PickKey(r, boxes);
                    Aabb b = RandomBox(r, 30);
                    tree.MoveProxy(boxes[key].proxy, b);
                    boxes[key] = (boxes[key].proxy, b);
                }
                else
                {
                    int key = PickKey(r, boxes);
                    tree.DestroyProxy(boxes[key].proxy);
                    boxes.Remove(key);
                }
                if (op % 200 == 0) tree.Validate();
            }
            tree.Validate();
            Assert.That(tree.ProxyCount, Is.EqualTo(boxes.Count));
            // Balance: height within a small factor of log2(n).
            Assert.That(tree.Height, Is.LessThan(4 * Math.Log(boxes.Count, 2) + 2));

            for (int q = 0; q < 200; q++)
            {
                Aabb query = RandomBox(r, 30);
                var c = new Collect { Found = new List<int>() };
                tree.Query(query, ref c);
                var expected = new List<int>();
                foreach (var kv in boxes) if (kv.Value.box.Overlaps(query)) expected.Add(kv.Key);
                c.Found.Sort();
                expected.Sort();
                Assert.That(c.Found, Is.EqualTo(expected));
            }
        }

        [Test]
        public void Ray_through_the_tree_visits_exactly_the_boxes_the_segment_crosses()
        {
            var r = new Random(5);
            var tree = new DynamicAabbTree();
            var boxes = new List<Aabb>();
            for (int i = 0; i < 500; i++)
            {
                Aabb b = RandomBox(r, 20);
                boxes.Add(b);
                tree.CreateProxy(b, i);
            }
            for (int q = 0; q < 100; q++)
            {
                Vector3 o = CollisionTestKit.RandomVector(r, 25), d = CollisionTestKit.RandomVector(r, 40);
                var c = new RayCollect { Found = new List<int>() };
                tree.RayCast(o, d, 1f, ref c);
                var expected = new List<int>();
                for (int i = 0; i < boxes.Count; i++)
                    if (SegmentHitsBox(boxes[i], o, d)) expected.Add(i);
                c.Found.Sort();
                Assert.That(c.Found, Is.EqualTo(expected));
            }
        }

        [Test]
        public void Sorted_insertion_stays_balanced_thanks_to_rotations()
        {
            // Boxes inserted in order along a line: the worst case for a naive tree.
            var tree = new DynamicAabbTree();
            for (int i = 0; i < 4096; i++)
                tree.CreateProxy(Aabb.FromCenterExtents(new Vector3(i, 0, 0), new Vector3(0.4f)), i);
            tree.Validate();
            Assert.That(tree.Height, Is.LessThanOrEqualTo(30));
        }

        static int PickKey(Random r, Dictionary<int, (int, Aabb)> d)
        {
            int skip = r.Next(d.Count);
            foreach (int k in d.Keys) if (skip-- == 0) return k;
            throw new InvalidOperationException();
        }

        // Reference segment/box test: the slab intervals in double precision.
        static bool SegmentHitsBox(Aabb b, Vector3 o, Vector3 d)
        {
            double t0 = 0, t1 = 1;
            for (int a = 0; a < 3; a++)
            {
                double oa = a == 0 ? o.X : a == 1 ? o.Y : o.Z, da = a == 0 ? d.X : a == 1 ? d.Y : d.Z;
                double lo = a == 0 ? b.Min.X : a == 1 ? b.Min.Y : b.Min.Z, hi = a == 0 ? b.Max.X : a == 1 ? b.Max.Y : b.Max.Z;
                if (Math.Abs(da) < 1e-12) { if (oa < lo || oa > hi) return false; continue; }
                double u = (lo - oa) / da, v = (hi - oa) / da;
                if (u > v) (u, v) = (v, u);
                t0 = Math.Max(t0, u);
                t1 = Math.Min(t1, v);
            }
            return t0 <= t1;
        }
    }
}
