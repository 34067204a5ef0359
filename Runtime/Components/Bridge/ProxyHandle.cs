using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// Identifies an entity registered with a <see cref="PhysicsBridge"/>: a slot and its
    /// generation, so a handle of an unregistered entity goes stale instead of naming the next
    /// one, and the id of the bridge's world, so a handle of another bridge is refused.
    /// <c>default</c> is "none".
    /// </summary>
    public readonly struct ProxyHandle : IEquatable<ProxyHandle>
    {
        /// <summary>The slot in the bridge's tables.</summary>
        public readonly int Index;
        /// <summary>The generation of the slot when the handle was issued; 0 means none.</summary>
        public readonly int Generation;

        /// <summary><see cref="World.Id"/> of the issuing bridge's world; another bridge refuses the handle.</summary>
        public readonly int WorldId;

        /// <summary>Builds a handle (the bridge issues them).</summary>
        public ProxyHandle(int index, int generation, int worldId)
        {
            Index = index;
            Generation = generation;
            WorldId = worldId;
        }

        /// <summary>Builds a handle with no world id (0), which every bridge refuses; kept for source compatibility.</summary>
        public ProxyHandle(int index, int generation) : this(index, generation, 0) { }

        /// <summary>True for the "none" handle.</summary>
        public bool IsNone => Generation == 0;

        /// <summary>Same slot and generation (the world id is left out, as for <see cref="BodyHandle"/>).</summary>
        public bool Equals(ProxyHandle other) => Index == other.Index && Generation == other.Generation;

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is ProxyHandle h && Equals(h);

        /// <inheritdoc/>
        public override int GetHashCode() => (Index * 397) ^ Generation;

        /// <summary>Same slot and generation.</summary>
        public static bool operator ==(ProxyHandle a, ProxyHandle b) => a.Equals(b);

        /// <summary>Different slot or generation.</summary>
        public static bool operator !=(ProxyHandle a, ProxyHandle b) => !a.Equals(b);

        /// <inheritdoc/>
        public override string ToString() => IsNone ? "ProxyHandle(none)" : $"ProxyHandle({Index}:{Generation})";
    }
}
