using System;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Joints by slot with generations (like <see cref="BodyStorage"/>), a dense list of live
    /// slots, and for every body the list of its joints (two edges per joint, edge = 2 slot +
    /// side) so that removing a body finds its joints without a search.
    /// </summary>
    internal sealed class JointStorage
    {
        public JointData[] Data = Array.Empty<JointData>();
        public int[] Generation = Array.Empty<int>();
        public int[] ActiveIndex = Array.Empty<int>();
        public string?[] Name = Array.Empty<string?>();
        /// <summary>Next edge in the body's list, per edge (2 per joint); -1 ends it.</summary>
        public int[] NextEdge = Array.Empty<int>();
        /// <summary>First edge of each body slot's list, -1 for none.</summary>
        public int[] FirstEdge = Array.Empty<int>();

        /// <summary>Live joint slots, densely packed (order changes on removal).</summary>
        public int[] Active = Array.Empty<int>();
        public int ActiveCount;

        int _capacity;
        int _slotCount;
        int[] _free = Array.Empty<int>();
        int _freeCount;

        public bool IsLive(JointHandle h) =>
            h.Generation != 0 && (uint)h.Index < (uint)_slotCount && Generation[h.Index] == h.Generation && ActiveIndex[h.Index] >= 0;

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
            int slot;
            if (_freeCount > 0) slot = _free[--_freeCount];
            else
            {
                if (_slotCount == _capacity) Grow(Math.Max(16, _capacity * 2));
                slot = _slotCount++;
            }
            Generation[slot]++;
            if (Generation[slot] <= 0) Generation[slot] = 1;
            ActiveIndex[slot] = ActiveCount;
            Active[ActiveCount++] = slot;
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
            int at = ActiveIndex[slot];
            int last = Active[--ActiveCount];
            Active[at] = last;
            ActiveIndex[last] = at;
            ActiveIndex[slot] = -1;
            Generation[slot]++;
            if (Generation[slot] <= 0) Generation[slot] = 1;
            Name[slot] = null;
            Data[slot] = default;
            if (_freeCount == _free.Length) Array.Resize(ref _free, Math.Max(16, _free.Length * 2));
            _free[_freeCount++] = slot;
        }

        void Grow(int capacity)
        {
            Array.Resize(ref Data, capacity);
            Array.Resize(ref Generation, capacity);
            Array.Resize(ref ActiveIndex, capacity);
            Array.Resize(ref Name, capacity);
            Array.Resize(ref NextEdge, 2 * capacity);
            Array.Resize(ref Active, capacity);
            for (int i = _capacity; i < capacity; i++) ActiveIndex[i] = -1;
            _capacity = capacity;
        }
    }
}
