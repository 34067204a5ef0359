using System;

namespace Fulcrum
{
    /// <summary>
    /// Slots with generations, a free list and a dense list of live slots: the bookkeeping
    /// behind every handle type (bodies, shapes, joints, soft bodies, bridge proxies). A slot's
    /// generation changes when it is taken and when it is freed, so a handle from before either
    /// no longer matches; live slots are also packed in <see cref="Active"/> so loops walk only
    /// real objects. Freed slots are reused last freed first, and a removal moves the last live
    /// slot into its place: both orders are part of every run's determinism.
    /// The owner keeps its own per-slot arrays at <see cref="Capacity"/> (see <see cref="Allocate"/>).
    /// </summary>
    internal sealed class SlotAllocator
    {
        int[] _free = Array.Empty<int>();
        int _freeCount;

        /// <summary>Generation of each slot; 0 only for a slot never used.</summary>
        public int[] Generation = Array.Empty<int>();
        /// <summary>Position of each slot in <see cref="Active"/>, -1 when the slot is free.</summary>
        public int[] ActiveIndex = Array.Empty<int>();
        /// <summary>Live slots, densely packed; order changes on removal (swap-remove).</summary>
        public int[] Active = Array.Empty<int>();
        /// <summary>How many entries of <see cref="Active"/> are used.</summary>
        public int ActiveCount;
        /// <summary>One past the highest slot ever used: the bound for slot-indexed loops.</summary>
        public int SlotCount;
        /// <summary>Length of the per-slot arrays.</summary>
        public int Capacity;

        /// <summary>True when <paramref name="index"/>/<paramref name="generation"/> name a live slot.</summary>
        public bool IsLive(int index, int generation) =>
            generation != 0 && (uint)index < (uint)SlotCount && Generation[index] == generation && ActiveIndex[index] >= 0;

        /// <summary>
        /// Takes a free slot and marks it live. When the slots ran out, capacity doubles and
        /// <paramref name="grew"/> tells the owner to resize its own arrays to <see cref="Capacity"/>.
        /// </summary>
        public int Allocate(out bool grew)
        {
            grew = false;
            int slot;
            if (_freeCount > 0) slot = _free[--_freeCount];
            else
            {
                if (SlotCount == Capacity)
                {
                    Grow(Math.Max(16, Capacity * 2));
                    grew = true;
                }
                slot = SlotCount++;
            }
            NextGeneration(slot);
            ActiveIndex[slot] = ActiveCount;
            Active[ActiveCount++] = slot;
            return slot;
        }

        /// <summary>
        /// The slot the next <see cref="Allocate"/> takes and the generation it gives it, without
        /// taking it: for owners that build the object first, so that a bad definition throws
        /// before anything changes.
        /// </summary>
        public int PeekNext(out int generation)
        {
            int slot = _freeCount > 0 ? _free[_freeCount - 1] : SlotCount;
            generation = After(slot < Generation.Length ? Generation[slot] : 0);
            return slot;
        }

        /// <summary>
        /// Puts the live slots in the order <paramref name="slots"/> lists them (a restore: the
        /// owner has checked that they are exactly the live slots, each once).
        /// </summary>
        public void SetActiveOrder(ReadOnlySpan<int> slots)
        {
            if (slots.Length != ActiveCount) throw new ArgumentException($"{slots.Length} slots given for {ActiveCount} live ones.", nameof(slots));
            for (int k = 0; k < slots.Length; k++)
            {
                Active[k] = slots[k];
                ActiveIndex[slots[k]] = k;
            }
        }

        /// <summary>Frees a live slot; handles to it go stale.</summary>
        public void Release(int slot)
        {
            int at = ActiveIndex[slot];
            int last = Active[--ActiveCount];
            Active[at] = last;
            ActiveIndex[last] = at;
            ActiveIndex[slot] = -1;
            NextGeneration(slot);
            if (_freeCount == _free.Length) Array.Resize(ref _free, Math.Max(16, _free.Length * 2));
            _free[_freeCount++] = slot;
        }

        void NextGeneration(int slot) => Generation[slot] = After(Generation[slot]);

        // Generations skip 0 ("none") when they wrap after 2^31 reuses.
        static int After(int generation) => generation + 1 <= 0 ? 1 : generation + 1;

        /// <summary>Writes the slots, generations, live list and free list (see <see cref="World.SaveState"/>).</summary>
        public void Save(StateWriter w)
        {
            w.Write(Capacity);
            w.Write(SlotCount);
            w.Write(ActiveCount);
            w.WriteArray(Generation, SlotCount);
            w.WriteArray(ActiveIndex, SlotCount);
            w.WriteArray(Active, ActiveCount);
            w.WriteArray(_free, _freeCount);
        }

        /// <summary>Reads what <see cref="Save"/> wrote into a new allocator, checking every index.</summary>
        public static SlotAllocator Load(StateReader r, string what)
        {
            var s = new SlotAllocator();
            int capacity = r.Count(what + " capacity", Limits.MaxReserve * 2);
            s.SlotCount = r.Count(what + " slot count", capacity);
            s.ActiveCount = r.Count(what + " live count", s.SlotCount);
            s.Capacity = capacity;
            s.Generation = r.ReadArrayExactly<int>(what + " generations", s.SlotCount);
            s.ActiveIndex = r.ReadArrayExactly<int>(what + " live positions", s.SlotCount);
            s.Active = r.ReadArrayExactly<int>(what + " live slots", s.ActiveCount);
            s._free = r.ReadArray<int>(what + " free slots");
            s._freeCount = s._free.Length;
            if (s._freeCount + s.ActiveCount != s.SlotCount) throw r.Error($"{what}: {s.ActiveCount} live and {s._freeCount} free slots do not add up to {s.SlotCount}.");
            Array.Resize(ref s.Generation, capacity);
            Array.Resize(ref s.ActiveIndex, capacity);
            Array.Resize(ref s.Active, capacity);
            for (int i = s.SlotCount; i < capacity; i++) s.ActiveIndex[i] = -1;
            for (int k = 0; k < s.ActiveCount; k++)
            {
                int slot = s.Active[k];
                if ((uint)slot >= (uint)s.SlotCount || s.ActiveIndex[slot] != k) throw r.Error($"{what}: live slot list entry {k} ({slot}) does not match its slot.");
            }
            for (int k = 0; k < s._freeCount; k++)
                if ((uint)s._free[k] >= (uint)s.SlotCount || s.ActiveIndex[s._free[k]] != -1) throw r.Error($"{what}: free slot {s._free[k]} is live or out of range.");
            return s;
        }

        void Grow(int capacity)
        {
            Array.Resize(ref Generation, capacity);
            Array.Resize(ref ActiveIndex, capacity);
            Array.Resize(ref Active, capacity);
            for (int i = Capacity; i < capacity; i++) ActiveIndex[i] = -1;
            Capacity = capacity;
        }
    }
}
