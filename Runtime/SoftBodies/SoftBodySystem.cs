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

        /// <summary>
        /// How many times more substeps a step is taken with again when a soft body blew apart
        /// in it (see <see cref="Step"/>); 1 takes no step again. Default 16, at most 64.
        /// </summary>
        public int RetrySubstepFactor
        {
            get => _retrySubstepFactor;
            set => _retrySubstepFactor = value >= 1 && value <= 64 ? value
                : throw new ArgumentOutOfRangeException(nameof(value), value, "RetrySubstepFactor must be 1 (never take a step again) to 64.");
        }
        int _retrySubstepFactor = 16;

        // Whether a soft body diverged in the last step: a body that blew apart again from where
        // it was put back is not retried step after step (each retry costs the substeps 16 times).
        bool _divergedLastStep;

        /// <summary>The most substeps a step taken again runs: <see cref="RetrySubstepFactor"/> times the step's, at most this (or the step's own if more).</summary>
        public const int MaxRetrySubsteps = 640;

        /// <inheritdoc/>
        /// <remarks>
        /// A step in which a soft body blows apart (a vertex non-finite or out of the world
        /// bounds, or a tet torn open; see <see cref="Diverged"/>) is taken again from its start,
        /// every soft body and the rigid bodies they moved put back, with
        /// <see cref="RetrySubstepFactor"/> times the substeps: a rigid body that struck the ground
        /// and spun up drags what is pinned to it across several elements in one substep, which
        /// finer substeps follow. Counted in <see cref="RetriedSteps"/>; only if the step blows
        /// apart again is the body put back and <see cref="Diverged"/> raised. A step right after
        /// one in which a body diverged is not taken again. Over soft fuzz seeds 0-999 this took
        /// the failing worlds from 14 to 11 (Documentation~/SoftSolvers.md).
        /// </remarks>
        public void Step(World world, float dt)
        {
            int count = _slots.ActiveCount;
            if (count == 0) return;
            IParallelScheduler? pool = world.ParallelScheduler();

            if (!TakeStep(world, dt, 1, pool) && !_divergedLastStep && RetrySubstepFactor > 1)
            {
                RetriedSteps++;
                for (int k = 0; k < count; k++) this[k].RollBack();
                _coupling.Restore();
                TakeStep(world, dt, RetrySubstepFactor, pool);
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
            _divergedLastStep = diverged;
            if (!diverged) return;
            // The rigid bodies as the rigid solve left them: what a diverging soft body pushed
            // onto them in the step is not kept. Then the reports, with the world consistent.
            _coupling.Restore();
            if (Diverged == null) return;
            for (int k = 0; k < count; k++)
                if (this[k].DivergedInStep) Diverged(this[k].Handle, world.StepIndex);
        }

        // The substeps of one step, finer by a factor of finer; false when a body blew apart.
        bool TakeStep(World world, float dt, int finer, IParallelScheduler? pool)
        {
            int count = _slots.ActiveCount;
            _coupling.Begin(world, dt);
            for (int k = 0; k < count; k++) this[k].BeginStep(dt, _coupling);
            _softContacts.FindPairs(this, world.Gravity.Length(), dt);
            // After BeginStep and the pairs: a Newton body's substeps depend on whether it touches anything.
            int substeps = 1;
            for (int k = 0; k < count; k++) substeps = Math.Max(substeps, this[k].SubstepsFor(dt));
            if (finer > 1) substeps = Math.Max(substeps, Math.Min(MaxRetrySubsteps, substeps * finer));
            float h = dt / substeps;
            _coupling.SetSubsteps(substeps);
            for (int s = 0; s < substeps; s++)
            {
                _coupling.BeginSubstep((s + 1f) / substeps, h);
                for (int k = 0; k < count; k++) this[k].Substep(h, _coupling, pool);
                if (_softContacts.PairCount > 0) _softContacts.Solve(h);
            }
            bool whole = true;
            for (int k = 0; k < count; k++) whole &= !this[k].Blown();
            return whole;
        }

        /// <summary>
        /// Raised (on the stepping thread) for a soft body whose vertices became non-finite or left
        /// the world bounds (±<see cref="Limits.MaxPosition"/> m), or that blew apart (a tet's
        /// volume ratio went beyond <see cref="SoftBody.MaxVolumeRatio"/>, growing more than
        /// <see cref="SoftBody.BlowUpGrowth"/> times in the step), in a step, with the step index,
        /// once the step taken again with finer substeps (<see cref="RetrySubstepFactor"/>) blew
        /// apart as well, or was not taken again (right after a divergence, or with the factor 1):
        /// the body was put back at its pose from the start of that step, at rest, and the rigid
        /// bodies the soft bodies moved in that step were put back as the rigid solve left them
        /// (what the soft bodies pushed onto them in the step is not kept).
        /// </summary>
        public event Action<SoftBodyHandle, long>? Diverged;

        /// <summary>
        /// Steps taken again with finer substeps because a soft body blew apart in them (see
        /// <see cref="Step"/>), since the system was created.
        /// </summary>
        public int RetriedSteps { get; private set; }

        /// <summary>Soft bodies that diverged since the system was created.</summary>
        public int DivergenceCount { get; private set; }

        /// <summary>The soft body that diverged last, and the step it diverged in.</summary>
        public SoftBodyHandle LastDiverged { get; private set; }

        /// <inheritdoc cref="LastDiverged"/>
        public long LastDivergedStep { get; private set; }
    }
}
