using System;

namespace Fulcrum
{
    /// <summary>
    /// Identifies a shape attached to a body in a <see cref="World"/>: a slot index, the generation of that slot and
    /// the id of the world that issued it.
    /// A handle whose shape was removed is stale: every World call that takes it throws
    /// <see cref="StaleHandleException"/> instead of touching whatever reuses the slot, and a handle from another world is
    /// refused the same way (it never reaches the other world's object in the same slot).
    /// <c>default</c> is "none" (generations start at 1).
    /// </summary>
    public readonly struct ShapeHandle : IEquatable<ShapeHandle>
    {
        /// <summary>The slot in the world's storage.</summary>
        public readonly int Index;
        /// <summary>The generation of the slot when the handle was issued; 0 means none.</summary>
        public readonly int Generation;
        /// <summary>
        /// <see cref="World.Id"/> of the world that issued the handle (ids start at 1 and are
        /// unique in the process). A world refuses a handle with another id. Not part of the
        /// simulation state: a restored world has its own id.
        /// </summary>
        public readonly int WorldId;

        /// <summary>Builds a handle of the world with id <paramref name="worldId"/>. Handles come from the world; user code rarely builds one.</summary>
        public ShapeHandle(int index, int generation, int worldId)
        {
            Index = index;
            Generation = generation;
            WorldId = worldId;
        }

        /// <summary>Builds a handle with no world id (0), which every world refuses; kept for source compatibility.</summary>
        public ShapeHandle(int index, int generation) : this(index, generation, 0) { }

        /// <summary>The "none" handle.</summary>
        public static ShapeHandle None => default;

        /// <summary>True for <see cref="None"/>.</summary>
        public bool IsNone => Generation == 0;

        /// <summary>
        /// Same slot and generation. The world id is left out on purpose: the handles of two
        /// worlds built the same way compare equal, which is how determinism checks compare two
        /// runs; which world accepts a handle is still decided by <see cref="WorldId"/>.
        /// </summary>
        public bool Equals(ShapeHandle other) => Index == other.Index && Generation == other.Generation;

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is ShapeHandle h && Equals(h);

        /// <inheritdoc/>
        public override int GetHashCode() => (Index * 397) ^ Generation;

        /// <summary>Same slot and generation (see <see cref="Equals(ShapeHandle)"/>).</summary>
        public static bool operator ==(ShapeHandle a, ShapeHandle b) => a.Equals(b);

        /// <summary>Different slot or generation.</summary>
        public static bool operator !=(ShapeHandle a, ShapeHandle b) => !a.Equals(b);

        /// <inheritdoc/>
        public override string ToString() => IsNone ? "ShapeHandle(none)" : $"ShapeHandle({Index}:{Generation} of world {WorldId})";
    }
}
