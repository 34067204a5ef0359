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
        // Slot, generation, world id and their equality, hash and text, shared by every handle type.
        internal readonly HandleId Id;

        /// <summary>Builds a handle (the bridge issues them).</summary>
        public ProxyHandle(int index, int generation, int worldId) => Id = new HandleId(index, generation, worldId);

        /// <summary>Builds a handle with no world id (0), which every bridge refuses; kept for source compatibility.</summary>
        public ProxyHandle(int index, int generation) : this(index, generation, 0) { }

        /// <summary>The slot in the bridge's tables.</summary>
        public int Index => Id.Index;
        /// <summary>The generation of the slot when the handle was issued; 0 means none.</summary>
        public int Generation => Id.Generation;
        /// <summary><see cref="World.Id"/> of the issuing bridge's world; another bridge refuses the handle.</summary>
        public int WorldId => Id.WorldId;

        /// <summary>True for the "none" handle.</summary>
        public bool IsNone => Id.IsNone;

        /// <summary>Same slot and generation (the world id is left out, as for <see cref="BodyHandle"/>).</summary>
        public bool Equals(ProxyHandle other) => Id.Equals(other.Id);

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is ProxyHandle h && Id.Equals(h.Id);

        /// <inheritdoc/>
        public override int GetHashCode() => Id.GetHashCode();

        /// <summary>Same slot and generation.</summary>
        public static bool operator ==(ProxyHandle a, ProxyHandle b) => a.Id.Equals(b.Id);

        /// <summary>Different slot or generation.</summary>
        public static bool operator !=(ProxyHandle a, ProxyHandle b) => !a.Id.Equals(b.Id);

        /// <inheritdoc/>
        public override string ToString() => Id.Format(nameof(ProxyHandle));
    }
}
