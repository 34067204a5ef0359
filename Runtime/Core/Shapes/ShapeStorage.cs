using System;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// Shapes in struct-of-arrays form, indexed by slot, with generations like
    /// <see cref="BodyStorage"/>. A body's shapes form a singly linked list through
    /// <see cref="NextInBody"/>.
    /// </summary>
    internal sealed class ShapeStorage
    {
        public ShapeGeometry[] Geometry = Array.Empty<ShapeGeometry>();
        public Pose[] LocalPose = Array.Empty<Pose>();
        public int[] Body = Array.Empty<int>();                // owning body slot
        public int[] NextInBody = Array.Empty<int>();          // -1 ends the list
        public float[] Density = Array.Empty<float>();
        public float[] Friction = Array.Empty<float>();
        public float[] Restitution = Array.Empty<float>();
        public CombineMode[] FrictionCombine = Array.Empty<CombineMode>();
        public CombineMode[] RestitutionCombine = Array.Empty<CombineMode>();
        public bool[] IsSensor = Array.Empty<bool>();
        public int[] Layer = Array.Empty<int>();
        public uint[] CollidesWith = Array.Empty<uint>();
        public ulong[] UserData = Array.Empty<ulong>();
        public Aabb[] WorldAabb = Array.Empty<Aabb>();         // tight bounds at the current pose
        public int[] ProxyId = Array.Empty<int>();             // broad-phase proxy, -1 when none
        public int[] Generation = Array.Empty<int>();
        public int[] ActiveIndex = Array.Empty<int>();

        /// <summary>Live shape slots, densely packed.</summary>
        public int[] Active = Array.Empty<int>();
        /// <summary>How many entries of <see cref="Active"/> are used.</summary>
        public int ActiveCount;

        int _capacity;
        int _slotCount;
        int[] _free = Array.Empty<int>();
        int _freeCount;

        /// <summary>One past the highest slot ever used.</summary>
        public int SlotCount => _slotCount;

        /// <summary>True when the handle names a live shape.</summary>
        public bool IsLive(ShapeHandle h) =>
            h.Generation != 0 && (uint)h.Index < (uint)_slotCount && Generation[h.Index] == h.Generation && ActiveIndex[h.Index] >= 0;

        /// <summary>Takes a free slot and marks it live.</summary>
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
            ProxyId[slot] = -1;
            return slot;
        }

        /// <summary>Frees a slot; its handle goes stale.</summary>
        public void Release(int slot)
        {
            int at = ActiveIndex[slot];
            int last = Active[--ActiveCount];
            Active[at] = last;
            ActiveIndex[last] = at;
            ActiveIndex[slot] = -1;
            Generation[slot]++;
            if (Generation[slot] <= 0) Generation[slot] = 1;
            Geometry[slot] = default;
            if (_freeCount == _free.Length) Array.Resize(ref _free, Math.Max(16, _free.Length * 2));
            _free[_freeCount++] = slot;
        }

        void Grow(int capacity)
        {
            Array.Resize(ref Geometry, capacity);
            Array.Resize(ref LocalPose, capacity);
            Array.Resize(ref Body, capacity);
            Array.Resize(ref NextInBody, capacity);
            Array.Resize(ref Density, capacity);
            Array.Resize(ref Friction, capacity);
            Array.Resize(ref Restitution, capacity);
            Array.Resize(ref FrictionCombine, capacity);
            Array.Resize(ref RestitutionCombine, capacity);
            Array.Resize(ref IsSensor, capacity);
            Array.Resize(ref Layer, capacity);
            Array.Resize(ref CollidesWith, capacity);
            Array.Resize(ref UserData, capacity);
            Array.Resize(ref WorldAabb, capacity);
            Array.Resize(ref ProxyId, capacity);
            Array.Resize(ref Generation, capacity);
            Array.Resize(ref ActiveIndex, capacity);
            Array.Resize(ref Active, capacity);
            for (int i = _capacity; i < capacity; i++) ActiveIndex[i] = -1;
            _capacity = capacity;
        }
    }
}
