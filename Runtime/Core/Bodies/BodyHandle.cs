using System;

namespace Fulcrum
{
    /// <summary>
    /// Identifies a rigid body in a <see cref="World"/>: a slot index and the generation of that slot.
    /// A handle whose body was removed is stale: every World call that takes it throws
    /// <see cref="StaleHandleException"/> instead of touching whatever reuses the slot.
    /// <c>default</c> is "none" (generations start at 1).
    /// </summary>
    public readonly struct BodyHandle : IEquatable<BodyHandle>
    {
        /// <summary>The slot in the world's storage.</summary>
        public readonly int Index;
        /// <summary>The generation of the slot when the handle was issued; 0 means none.</summary>
        public readonly int Generation;

        /// <summary>Builds a handle. Handles come from the world; user code rarely builds one.</summary>
        public BodyHandle(int index, int generation)
        {
            Index = index;
            Generation = generation;
        }

        /// <summary>The "none" handle.</summary>
        public static BodyHandle None => default;

        /// <summary>True for <see cref="None"/>.</summary>
        public bool IsNone => Generation == 0;

        /// <inheritdoc/>
        public bool Equals(BodyHandle other) => Index == other.Index && Generation == other.Generation;

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is BodyHandle h && Equals(h);

        /// <inheritdoc/>
        public override int GetHashCode() => (Index * 397) ^ Generation;

        /// <summary>Same slot and generation.</summary>
        public static bool operator ==(BodyHandle a, BodyHandle b) => a.Equals(b);

        /// <summary>Different slot or generation.</summary>
        public static bool operator !=(BodyHandle a, BodyHandle b) => !a.Equals(b);

        /// <inheritdoc/>
        public override string ToString() => IsNone ? "BodyHandle(none)" : $"BodyHandle({Index}:{Generation})";
    }
}
