using System;

namespace Fulcrum
{
    /// <summary>
    /// What every handle is (<see cref="BodyHandle"/>, <see cref="ShapeHandle"/>,
    /// <see cref="JointHandle"/>, <see cref="SoftBodyHandle"/>, the bridge's ProxyHandle): a
    /// slot of a <see cref="SlotAllocator"/>, the generation of that slot when the handle was
    /// issued, and the id of the world that issued it. The public handle types wrap one each, so
    /// that a body handle cannot be passed where a joint handle is expected, and share this one
    /// definition of none, equality, hashing and text.
    /// </summary>
    internal readonly struct HandleId : IEquatable<HandleId>
    {
        /// <summary>The slot in the issuer's <see cref="SlotAllocator"/>.</summary>
        public readonly int Index;
        /// <summary>The generation of the slot when the handle was issued; 0 means none (generations start at 1).</summary>
        public readonly int Generation;
        /// <summary><see cref="World.Id"/> of the issuing world; 0 for a handle built without one, which every world refuses.</summary>
        public readonly int WorldId;

        public HandleId(int index, int generation, int worldId)
        {
            Index = index;
            Generation = generation;
            WorldId = worldId;
        }

        /// <summary>True for the "none" handle (<c>default</c>).</summary>
        public bool IsNone => Generation == 0;

        /// <summary>
        /// Same slot and generation. The world id is left out on purpose: the handles of two
        /// worlds built the same way compare equal, which is how determinism checks compare two
        /// runs; which world accepts a handle is still decided by <see cref="WorldId"/>.
        /// </summary>
        public bool Equals(HandleId other) => Index == other.Index && Generation == other.Generation;

        public override bool Equals(object? obj) => obj is HandleId h && Equals(h);

        public override int GetHashCode() => (Index * 397) ^ Generation;

        /// <summary>The text of a handle of type <paramref name="type"/>, e.g. <c>BodyHandle(3:1 of world 2)</c>.</summary>
        public string Format(string type) => IsNone ? type + "(none)" : $"{type}({Index}:{Generation} of world {WorldId})";
    }
}
