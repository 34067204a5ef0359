using System;

namespace Fulcrum
{
    /// <summary>
    /// Identifies a soft body in a <see cref="World"/>: a slot index, the generation of that slot and
    /// the id of the world that issued it.
    /// A handle whose soft body was removed is stale: every World call that takes it throws
    /// <see cref="StaleHandleException"/> instead of touching whatever reuses the slot, and a handle from another world is
    /// refused the same way (it never reaches the other world's object in the same slot).
    /// <c>default</c> is "none" (generations start at 1).
    /// </summary>
    public readonly struct SoftBodyHandle : IEquatable<SoftBodyHandle>
    {
        // Slot, generation, world id and their equality, hash and text, shared by every handle type.
        internal readonly HandleId Id;

        /// <summary>Builds a handle of the world with id <paramref name="worldId"/>. Handles come from the world; user code rarely builds one.</summary>
        public SoftBodyHandle(int index, int generation, int worldId) => Id = new HandleId(index, generation, worldId);

        /// <summary>Builds a handle with no world id (0), which every world refuses; kept for source compatibility.</summary>
        public SoftBodyHandle(int index, int generation) : this(index, generation, 0) { }

        /// <summary>The slot in the world's storage.</summary>
        public int Index => Id.Index;
        /// <summary>The generation of the slot when the handle was issued; 0 means none.</summary>
        public int Generation => Id.Generation;
        /// <summary>
        /// <see cref="World.Id"/> of the world that issued the handle (ids start at 1 and are
        /// unique in the process). A world refuses a handle with another id. Not part of the
        /// simulation state: a restored world has its own id.
        /// </summary>
        public int WorldId => Id.WorldId;

        /// <summary>The "none" handle.</summary>
        public static SoftBodyHandle None => default;

        /// <summary>True for <see cref="None"/>.</summary>
        public bool IsNone => Id.IsNone;

        /// <summary>
        /// Same slot and generation. The world id is left out on purpose: the handles of two
        /// worlds built the same way compare equal, which is how determinism checks compare two
        /// runs; which world accepts a handle is still decided by <see cref="WorldId"/>.
        /// </summary>
        public bool Equals(SoftBodyHandle other) => Id.Equals(other.Id);

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is SoftBodyHandle h && Id.Equals(h.Id);

        /// <inheritdoc/>
        public override int GetHashCode() => Id.GetHashCode();

        /// <summary>Same slot and generation (see <see cref="Equals(SoftBodyHandle)"/>).</summary>
        public static bool operator ==(SoftBodyHandle a, SoftBodyHandle b) => a.Id.Equals(b.Id);

        /// <summary>Different slot or generation.</summary>
        public static bool operator !=(SoftBodyHandle a, SoftBodyHandle b) => !a.Id.Equals(b.Id);

        /// <inheritdoc/>
        public override string ToString() => Id.Format(nameof(SoftBodyHandle));
    }
}
