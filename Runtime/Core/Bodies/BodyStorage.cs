using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// Body state in struct-of-arrays form, indexed by slot. Slots are reused through a free
    /// list; each reuse bumps the slot's generation so old handles go stale. Live slots are
    /// also kept densely in <see cref="SlotStorage.Active"/> so that stage loops walk only real bodies.
    /// Internal: the public view is <see cref="BodyRef"/>.
    /// </summary>
    internal sealed partial class BodyStorage : SlotStorage
    {
        // Hot: read or written by every stage loop.
        public Vector3[] Position = Array.Empty<Vector3>();          // body origin, world
        public Quaternion[] Rotation = Array.Empty<Quaternion>();
        public Vector3[] Center = Array.Empty<Vector3>();            // centre of mass, world
        public Vector3[] LinearVelocity = Array.Empty<Vector3>();    // of the centre of mass
        public Vector3[] AngularVelocity = Array.Empty<Vector3>();   // world
        public float[] InverseMass = Array.Empty<float>();
        public Mat3[] InverseInertiaWorld = Array.Empty<Mat3>();     // R_p diag(1/I) R_p^T, refreshed with the pose
        public BodyType[] Type = Array.Empty<BodyType>();
        public bool[] Awake = Array.Empty<bool>();

        // Warm: read during integration.
        public Vector3[] Force = Array.Empty<Vector3>();             // accumulated until the end of the step
        public Vector3[] Torque = Array.Empty<Vector3>();
        public Vector3[] InverseInertiaPrincipal = Array.Empty<Vector3>(); // 1/I along the principal axes (0 = locked)
        public Quaternion[] InertiaFrame = Array.Empty<Quaternion>();      // principal axes in the body frame
        public Vector3[] LocalCenter = Array.Empty<Vector3>();
        public float[] Radius = Array.Empty<float>();                // farthest shape point from the centre of mass, m (speed cap of spin)
        public float[] LinearDamping = Array.Empty<float>();
        public float[] AngularDamping = Array.Empty<float>();
        public float[] GravityScale = Array.Empty<float>();
        public AxisLocks[] Locks = Array.Empty<AxisLocks>();         // None for almost every body: one byte read per integration
        public Vector3[] PreviousPosition = Array.Empty<Vector3>();  // pose at the start of the last step, for interpolation
        public Quaternion[] PreviousRotation = Array.Empty<Quaternion>();
        public Vector3[] StartLinearVelocity = Array.Empty<Vector3>();  // velocities at the start of the last step (before the solve),
        public Vector3[] StartAngularVelocity = Array.Empty<Vector3>(); // from which the soft-body stage re-integrates the bodies it touches

        // Cold: touched on creation, edits and rare events.
        public float[] Mass = Array.Empty<float>();
        public Mat3[] InertiaLocal = Array.Empty<Mat3>();            // about the centre, body frame
        public float[] MassOverride = Array.Empty<float>();          // 0: from shapes
        public bool[] AllowSleep = Array.Empty<bool>();
        public bool[] Ccd = Array.Empty<bool>();
        public float[] SleepTime = Array.Empty<float>();
        public bool[] HasKinematicTarget = Array.Empty<bool>();
        public bool[] VelocityFromTarget = Array.Empty<bool>();
        public Vector3[] TargetPosition = Array.Empty<Vector3>();
        public Quaternion[] TargetRotation = Array.Empty<Quaternion>();
        public int[] FirstShape = Array.Empty<int>();                // head of the body's shape list, -1 for none
        public string?[] Name = Array.Empty<string?>();
        public ulong[] UserData = Array.Empty<ulong>();

        /// <summary>True when the handle names a live body.</summary>
        public bool IsLive(BodyHandle h) => _slots.IsLive(h.Index, h.Generation);

        /// <summary>Takes a free slot (growing the arrays if needed) and marks it live.</summary>
        public int Allocate()
        {
            int slot = _slots.Allocate(out bool grew);
            if (grew) Grow(_slots.Capacity);
            return slot;
        }

        /// <summary>Returns a slot to the free list; its handle goes stale.</summary>
        public void Release(int slot)
        {
            _slots.Release(slot);
            Name[slot] = null;
        }

        void Grow(int capacity)
        {
            var columns = new ColumnResize(capacity);
            Columns(ref columns);
        }

        /// <summary>
        /// Refreshes the world inverse inertia of a slot from its rotation, projected onto the
        /// free rotation axes when some are locked (<see cref="Dynamics.AxisLockMath.ProjectInertia"/>).
        /// </summary>
        public void UpdateWorldInertia(int slot)
        {
            Mat3 r = Mat3.FromQuaternion(Rotation[slot] * InertiaFrame[slot]);
            Mat3 inverse = Mat3.RotateDiagonal(r, InverseInertiaPrincipal[slot]);
            AxisLocks locks = Locks[slot] & AxisLocks.Angular;
            InverseInertiaWorld[slot] = locks == 0 ? inverse : Dynamics.AxisLockMath.ProjectInertia(inverse, locks);
        }

        /// <summary>Sets the origin from the world centre of mass (after the centre moved).</summary>
        public void SyncOriginFromCenter(int slot) =>
            Position[slot] = Center[slot] - Vector3.Transform(LocalCenter[slot], Rotation[slot]);

        /// <summary>Sets the world centre of mass from the origin (after the origin moved).</summary>
        public void SyncCenterFromOrigin(int slot) =>
            Center[slot] = Position[slot] + Vector3.Transform(LocalCenter[slot], Rotation[slot]);
    }
}
