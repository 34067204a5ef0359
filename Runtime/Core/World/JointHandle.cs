using System;

namespace Fulcrum
{
    /// <summary>
    /// Identifies a joint in a <see cref="World"/>: a slot index and the generation of that slot.
    /// A handle whose joint was removed is stale: every World call that takes it throws
    /// <see cref="StaleHandleException"/> instead of touching whatever reuses the slot.
    /// <c>default</c> is "none" (generations start at 1).
    /// </summary>
    public readonly struct JointHandle : IEquatable<JointHandle>
    {
        /// <summary>The slot in the world's storage.</summary>
        public readonly int Index;
        /// <summary>The generation of the slot when the handle was issued; 0 means none.</summary>
        public readonly int Generation;

        /// <summary>Builds a handle. Handles come from the world; user code rarely builds one.</summary>
        public JointHandle(int index, int generation)
        {
            Index = index;
            Generation = generation;
        }

        /// <summary>The "none" handle.</summary>
        public static JointHandle None => default;

        /// <summary>True for <see cref="None"/>.</summary>
        public bool IsNone => Generation == 0;

        /// <inheritdoc/>
        public bool Equals(JointHandle other) => Index == other.Index && Generation == other.Generation;

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is JointHandle h && Equals(h);

        /// <inheritdoc/>
        public override int GetHashCode() => (Index * 397) ^ Generation;

        /// <summary>Same slot and generation.</summary>
        public static bool operator ==(JointHandle a, JointHandle b) => a.Equals(b);

        /// <summary>Different slot or generation.</summary>
        public static bool operator !=(JointHandle a, JointHandle b) => !a.Equals(b);

        /// <inheritdoc/>
        public override string ToString() => IsNone ? "JointHandle(none)" : $"JointHandle({Index}:{Generation})";
    }
}
