using System;

namespace Fulcrum
{
    /// <summary>
    /// Identifies a shape attached to a body in a <see cref="World"/>: a slot index and the generation of that slot.
    /// A handle whose shape was removed is stale: every World call that takes it throws
    /// <see cref="StaleHandleException"/> instead of touching whatever reuses the slot.
    /// <c>default</c> is "none" (generations start at 1).
    /// </summary>
    public readonly struct ShapeHandle : IEquatable<ShapeHandle>
    {
        /// <summary>The slot in the world's storage.</summary>
        public readonly int Index;
        /// <summary>The generation of the slot when the handle was issued; 0 means none.</summary>
        public readonly int Generation;

        /// <summary>Builds a handle. Handles come from the world; user code rarely builds one.</summary>
        public ShapeHandle(int index, int generation)
        {
            Index = index;
            Generation = generation;
        }

        /// <summary>The "none" handle.</summary>
        public static ShapeHandle None => default;

        /// <summary>True for <see cref="None"/>.</summary>
        public bool IsNone => Generation == 0;

        /// <inheritdoc/>
        public bool Equals(ShapeHandle other) => Index == other.Index && Generation == other.Generation;

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is ShapeHandle h && Equals(h);

        /// <inheritdoc/>
        public override int GetHashCode() => (Index * 397) ^ Generation;

        /// <summary>Same slot and generation.</summary>
        public static bool operator ==(ShapeHandle a, ShapeHandle b) => a.Equals(b);

        /// <summary>Different slot or generation.</summary>
        public static bool operator !=(ShapeHandle a, ShapeHandle b) => !a.Equals(b);

        /// <inheritdoc/>
        public override string ToString() => IsNone ? "ShapeHandle(none)" : $"ShapeHandle({Index}:{Generation})";
    }
}
