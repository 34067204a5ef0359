namespace Fulcrum
{
    /// <summary>
    /// The slot bookkeeping shared by the slot-indexed storages (bodies, shapes, joints): a
    /// <see cref="SlotAllocator"/> and its views. Each storage keeps its own struct-of-arrays
    /// columns, indexed by slot, and grows them when the allocator grows.
    /// </summary>
    internal abstract class SlotStorage
    {
        private protected SlotAllocator _slots = new SlotAllocator();

        /// <summary>The allocator itself, for checking handles (<see cref="World.LiveSlot"/>).</summary>
        public SlotAllocator Slots => _slots;

        /// <summary>Generation of each slot (see <see cref="SlotAllocator"/>).</summary>
        public int[] Generation => _slots.Generation;
        /// <summary>Position of each slot in <see cref="Active"/>, -1 when free.</summary>
        public int[] ActiveIndex => _slots.ActiveIndex;
        /// <summary>Live slots, densely packed; order changes on removal (swap-remove).</summary>
        public int[] Active => _slots.Active;
        /// <summary>How many entries of <see cref="Active"/> are used.</summary>
        public int ActiveCount => _slots.ActiveCount;
        /// <summary>One past the highest slot ever used: the bound for slot-indexed loops.</summary>
        public int SlotCount => _slots.SlotCount;
    }
}
