using System;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Joints by slot with generations (like <see cref="BodyStorage"/>), a dense list of live
    /// slots, and for every body the list of its joints (two edges per joint, edge = 2 slot +
    /// side) so that removing a body finds its joints without a search.
    /// </summary>
    internal sealed partial class JointStorage : SlotStorage
    {
        public JointData[] Data = Array.Empty<JointData>();
        public string?[] Name = Array.Empty<string?>();
        /// <summary>Next edge in the body's list, per edge (2 per joint); -1 ends it.</summary>
        public int[] NextEdge = Array.Empty<int>();
        /// <summary>First edge of each body slot's list, -1 for none.</summary>
        public int[] FirstEdge = Array.Empty<int>();

        public bool IsLive(JointHandle h) => _slots.IsLive(h.Index, h.Generation);

        /// <summary>Makes sure every body slot below <paramref name="bodySlots"/> has an edge list head.</summary>
        public void EnsureBodies(int bodySlots)
        {
            if (FirstEdge.Length >= bodySlots) return;
            int old = FirstEdge.Length;
            Array.Resize(ref FirstEdge, Math.Max(bodySlots, Math.Max(16, old * 2)));
            for (int i = old; i < FirstEdge.Length; i++) FirstEdge[i] = -1;
        }

        public int Allocate()
        {
            int slot = _slots.Allocate(out bool grew);
            if (grew) Grow(_slots.Capacity);
            return slot;
        }

        /// <summary>Links the joint into its bodies' lists (world ends are not listed).</summary>
        public void Link(int slot)
        {
            ref JointData j = ref Data[slot];
            if (j.BodyA >= 0) Push(j.BodyA, 2 * slot);
            if (j.BodyB >= 0) Push(j.BodyB, 2 * slot + 1);
        }

        void Push(int body, int edge)
        {
            NextEdge[edge] = FirstEdge[body];
            FirstEdge[body] = edge;
        }

        void Unlink(int body, int edge)
        {
            if (FirstEdge[body] == edge)
            {
                FirstEdge[body] = NextEdge[edge];
                return;
            }
            for (int e = FirstEdge[body]; e >= 0; e = NextEdge[e])
            {
                if (NextEdge[e] == edge)
                {
                    NextEdge[e] = NextEdge[edge];
                    return;
                }
            }
        }

        public void Release(int slot)
        {
            ref JointData j = ref Data[slot];
            if (j.BodyA >= 0) Unlink(j.BodyA, 2 * slot);
            if (j.BodyB >= 0) Unlink(j.BodyB, 2 * slot + 1);
            _slots.Release(slot);
            Name[slot] = null;
            Data[slot] = default;
        }

        void Grow(int capacity)
        {
            Array.Resize(ref Data, capacity);
            Array.Resize(ref Name, capacity);
            Array.Resize(ref NextEdge, 2 * capacity);
        }
    }
}
