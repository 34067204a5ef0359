using System;
using System.Collections.Generic;
using Fulcrum.Collision;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Makes two shapes ignore each other (no contacts, no trigger overlaps) or collide
        /// again, whatever their layers say (Unity's Physics.IgnoreCollision). Ignoring ends the
        /// contacts they have now (with end events); colliding again lets the next step find
        /// them if they overlap. The setting lasts until either shape is removed. Wakes both
        /// bodies. Not during a step.
        /// </summary>
        public void IgnoreCollision(ShapeHandle a, ShapeHandle b, bool ignore = true)
        {
            int sa = ShapeSlot(a), sb = ShapeSlot(b);
            ThrowIfInStep();
            if (sa == sb) throw new ArgumentException("IgnoreCollision needs two different shapes; both handles name the same one.", nameof(b));
            ulong key = PairMap.Key(sa, sb);
            bool now = IgnoredPairs.Find(key) >= 0;
            if (now == ignore) return;
            if (ignore)
            {
                IgnoredPairs.Add(key, 0);
                IgnoredPairList.Add(key);
                int c = ContactGraph.Find(sa, sb);
                if (c >= 0)
                {
                    if ((ContactGraph.Contacts[c].Flags & ContactFlags.Touching) != 0) RecordRemovalEnd(c);
                    ContactGraph.Destroy(c);
                }
            }
            else
            {
                IgnoredPairs.Remove(key);
                IgnoredPairList.Remove(key);
                // The pair filter runs on new fat-box overlaps only: queue the proxy for a new search.
                if (Shapes.ProxyId[sa] >= 0) _broadPhase.Requeue(Shapes.ProxyId[sa]);
            }
            Wake(Shapes.Body[sa]);
            Wake(Shapes.Body[sb]);
        }

        /// <summary>Whether <see cref="IgnoreCollision"/> set the two shapes to ignore each other.</summary>
        public bool GetIgnoreCollision(ShapeHandle a, ShapeHandle b)
        {
            int sa = ShapeSlot(a), sb = ShapeSlot(b);
            return IgnoredPairs.Count > 0 && IgnoredPairs.Find(PairMap.Key(sa, sb)) >= 0;
        }

        /// <summary>The pair filter's check: true when the two shape slots ignore each other.</summary>
        internal bool IgnoresPair(int shapeA, int shapeB) =>
            IgnoredPairs.Count > 0 && IgnoredPairs.Find(PairMap.Key(shapeA, shapeB)) >= 0;

        // A removed shape forgets its ignored pairs, so that a new shape in its slot starts clean.
        void ForgetIgnoredPairs(int shape)
        {
            if (IgnoredPairs.Count == 0) return;
            for (int k = IgnoredPairList.Count - 1; k >= 0; k--)
            {
                ulong key = IgnoredPairList[k];
                if ((int)(key >> 32) != shape && (int)(uint)key != shape) continue;
                IgnoredPairs.Remove(key);
                IgnoredPairList.RemoveAt(k);
            }
        }

        /// <summary>Shape pairs that ignore each other (values unused), for the pair filter's lookup.</summary>
        internal PairMap IgnoredPairs = new PairMap();

        /// <summary>The same pairs in the order they were set, to find a removed shape's pairs.</summary>
        internal List<ulong> IgnoredPairList = new List<ulong>();
    }
}
