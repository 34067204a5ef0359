using System;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The soft bodies of one world and the <see cref="StepStage.SoftBodies"/> stage that steps
    /// them. Installed as <see cref="World.SoftBodyStage"/> by the first
    /// <see cref="SoftBodyWorldExtensions.CreateSoftBody"/>. All bodies advance through the
    /// substeps together (the largest substep count any of them asks for), so a rigid body
    /// touched by two soft bodies sees both at the same instants.
    /// Reads and writes the rigid bodies it touches (pose, velocity) through <see cref="RigidCoupling"/>.
    /// Bodies that touch each other are resolved after every substep by <see cref="SoftSoftContacts"/>,
    /// and a Newton body's step takes the other body's inertia in as well (see ImplicitNewtonSolver.SoftContacts).
    /// </summary>
    public sealed partial class SoftBodySystem : ISoftBodyStage
    {
        readonly World _world;
        // Slots, generations and the stepping order (live slots, swap-removed) come from Core's
        // allocator, as for rigid bodies; the bodies themselves are kept by slot here.
        readonly SlotAllocator _slots = new SlotAllocator();
        SoftBody?[] _bodies = Array.Empty<SoftBody?>();
        readonly RigidCoupling _coupling = new RigidCoupling();
        readonly SoftSoftContacts _softContacts = new SoftSoftContacts();

        internal SoftBodySystem(World world) => _world = world;

        /// <summary>The system of a world, or null when it has no soft-body stage yet.</summary>
        public static SoftBodySystem? Of(World world) => world.SoftBodyStage as SoftBodySystem;

        /// <summary>Live soft bodies.</summary>
        public int Count => _slots.ActiveCount;

        /// <inheritdoc/>
        public bool HasWork => _slots.ActiveCount > 0;

        /// <summary>The live body at position <paramref name="index"/> (0 .. Count - 1, creation order with removals swapped in).</summary>
        public SoftBody this[int index] =>
            (uint)index < (uint)_slots.ActiveCount ? _bodies[_slots.Active[index]]! : throw new ArgumentOutOfRangeException(nameof(index), $"{index} is not below Count ({Count}).");

        internal SoftBodyHandle Add(in SoftBodyDef def)
        {
            int slot = _slots.PeekNext(out int generation);
            // Build first: a bad def throws before the system changes.
            var body = new SoftBody(_world, slot, generation, def);
            _slots.Allocate(out bool grew);
            if (grew) Array.Resize(ref _bodies, _slots.Capacity);
            _bodies[slot] = body;
            return body.Handle;
        }

        internal void Remove(SoftBodyHandle handle)
        {
            int slot = Slot(handle);
            _bodies[slot]!.Destroyed = true;
            _bodies[slot] = null;
            _slots.Release(slot);
        }

        internal bool IsLive(SoftBodyHandle handle) => handle.WorldId == _world.Id && _slots.IsLive(handle.Index, handle.Generation);

        internal SoftBody Get(SoftBodyHandle handle) => _bodies[Slot(handle)]!;

        int Slot(SoftBodyHandle handle) => _world.LiveSlot(handle.Id, _slots, nameof(SoftBodyHandle), "soft body", "destroyed");

        /// <inheritdoc/>
        public void Step(World world, float dt)
        {
            int count = _slots.ActiveCount;
            if (count == 0) return;
            IParallelScheduler? pool = world.ParallelScheduler();

            _coupling.Begin(world, dt);
            for (int k = 0; k < count; k++) this[k].BeginStep(dt, _coupling);
            _softContacts.FindPairs(this, world.Gravity.Length(), dt);
            // After BeginStep and the pairs: a Newton body's substeps depend on whether it touches anything.
            int substeps = 1;
            for (int k = 0; k < count; k++) substeps = Math.Max(substeps, this[k].SubstepsFor(dt));
            float h = dt / substeps;
            _coupling.SetSubsteps(substeps);
            for (int s = 0; s < substeps; s++)
            {
                _coupling.BeginSubstep((s + 1f) / substeps, h);
                for (int k = 0; k < count; k++) this[k].Substep(h, _coupling, pool);
                if (_softContacts.PairCount > 0) _softContacts.Solve(h);
            }
            bool diverged = false;
            for (int k = 0; k < count; k++)
            {
                SoftBody body = this[k];
                body.EndStep(dt);
                if (body.KeepFinite()) continue;
                diverged = true;
                DivergenceCount++;
                LastDiverged = body.Handle;
                LastDivergedStep = world.StepIndex;
            }
            if (!diverged) return;
            // The rigid bodies as the rigid solve left them: what a diverging soft body pushed
            // onto them in the step is not kept. Then the reports, with the world consistent.
            _coupling.Restore();
            if (Diverged == null) return;
            for (int k = 0; k < count; k++)
                if (this[k].DivergedInStep) Diverged(this[k].Handle, world.StepIndex);
        }

        /// <summary>
        /// Raised (on the stepping thread) for a soft body whose vertices became non-finite or left
        /// the world bounds (±<see cref="Limits.MaxPosition"/> m), or that blew apart (a tet's
        /// volume ratio went beyond <see cref="SoftBody.MaxVolumeRatio"/>, growing more than
        /// <see cref="SoftBody.BlowUpGrowth"/> times in the step), in a step, with the step index:
        /// the body was put back at its pose from the start of that step, at rest, and the rigid
        /// bodies the soft bodies moved in that step were put back as the rigid solve left them
        /// (what the soft bodies pushed onto them in the step is not kept).
        /// </summary>
        public event Action<SoftBodyHandle, long>? Diverged;

        /// <summary>Soft bodies that diverged since the system was created.</summary>
        public int DivergenceCount { get; private set; }

        /// <summary>The soft body that diverged last, and the step it diverged in.</summary>
        public SoftBodyHandle LastDiverged { get; private set; }

        /// <inheritdoc cref="LastDiverged"/>
        public long LastDivergedStep { get; private set; }
    }
}
