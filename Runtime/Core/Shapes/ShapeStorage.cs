using System;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// Shapes in struct-of-arrays form, indexed by slot, with generations like
    /// <see cref="BodyStorage"/>. A body's shapes form a singly linked list through
    /// <see cref="NextInBody"/>.
    /// </summary>
    internal sealed partial class ShapeStorage : SlotStorage
    {
        public ShapeGeometry[] Geometry = Array.Empty<ShapeGeometry>();
        public Pose[] LocalPose = Array.Empty<Pose>();
        public int[] Body = Array.Empty<int>();                // owning body slot
        public int[] NextInBody = Array.Empty<int>();          // -1 ends the list
        public float[] Density = Array.Empty<float>();
        public float[] Friction = Array.Empty<float>();
        public float[] Restitution = Array.Empty<float>();
        public CombineMode[] FrictionCombine = Array.Empty<CombineMode>();
        public CombineMode[] RestitutionCombine = Array.Empty<CombineMode>();
        public bool[] IsSensor = Array.Empty<bool>();
        public int[] Layer = Array.Empty<int>();
        public uint[] CollidesWith = Array.Empty<uint>();
        public ulong[] UserData = Array.Empty<ulong>();
        public Aabb[] WorldAabb = Array.Empty<Aabb>();         // tight bounds at the current pose
        public int[] ProxyId = Array.Empty<int>();             // broad-phase proxy, -1 when none
        /// <summary>The world pose of shape <paramref name="shape"/>: its body's pose times its local pose.</summary>
        public Pose WorldPose(int shape, BodyStorage bodies)
        {
            int b = Body[shape];
            return new Pose(bodies.Position[b], bodies.Rotation[b]) * LocalPose[shape];
        }

        /// <summary>True when the handle names a live shape.</summary>
        public bool IsLive(ShapeHandle h) => _slots.IsLive(h.Index, h.Generation);

        /// <summary>Takes a free slot and marks it live.</summary>
        public int Allocate()
        {
            int slot = _slots.Allocate(out bool grew);
            if (grew) Grow(_slots.Capacity);
            ProxyId[slot] = -1;
            return slot;
        }

        /// <summary>Frees a slot; its handle goes stale.</summary>
        public void Release(int slot)
        {
            _slots.Release(slot);
            Geometry[slot] = default;
        }

        void Grow(int capacity)
        {
            Array.Resize(ref Geometry, capacity);
            var columns = new ColumnResize(capacity);
            Columns(ref columns);
        }
    }
}
