using System;
using System.Collections.Generic;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The soft bodies of one world and the <see cref="StepStage.SoftBodies"/> stage that steps
    /// them. Installed as <see cref="World.SoftBodyStage"/> by the first
    /// <see cref="SoftBodyWorldExtensions.CreateSoftBody"/>. All bodies advance through the
    /// substeps together (the largest substep count any of them asks for), so a rigid body
    /// touched by two soft bodies sees both at the same instants.
    /// Reads and writes the rigid bodies it touches (pose, velocity) through <see cref="RigidCoupling"/>.
    /// Bodies that touch each other are resolved after every substep by <see cref="SoftSoftContacts"/>.
    /// </summary>
    public sealed partial class SoftBodySystem : ISoftBodyStage
    {
        readonly World _world;
        readonly List<SoftBody?> _slots = new List<SoftBody?>();
        readonly List<int> _generations = new List<int>();
        readonly Stack<int> _free = new Stack<int>();
        readonly List<SoftBody> _active = new List<SoftBody>();
        readonly RigidCoupling _coupling = new RigidCoupling();
        readonly SoftSoftContacts _softContacts = new SoftSoftContacts();

        internal SoftBodySystem(World world) => _world = world;

        /// <summary>The system of a world, or null when it has no soft-body stage yet.</summary>
        public static SoftBodySystem? Of(World world) => world.SoftBodyStage as SoftBodySystem;

        /// <summary>Live soft bodies.</summary>
        public int Count => _active.Count;

        /// <inheritdoc/>
        public bool HasWork => _active.Count > 0;

        /// <summary>The live body at position <paramref name="index"/> (0 .. Count - 1, creation order with removals swapped in).</summary>
        public SoftBody this[int index] => _active[index];

        internal SoftBodyHandle Add(in SoftBodyDef def)
        {
            int slot = _free.Count > 0 ? _free.Peek() : _slots.Count;
            int generation = (slot < _generations.Count ? _generations[slot] : 0) + 1;
            if (generation <= 0) generation = 1;
            // Build first: a bad def throws before the system changes.
            var body = new SoftBody(_world, slot, generation, def);
            if (_free.Count > 0) _free.Pop();
            if (slot == _slots.Count)
            {
                _slots.Add(body);
                _generations.Add(generation);
            }
            else
            {
                _slots[slot] = body;
                _generations[slot] = generation;
            }
            _active.Add(body);
            return body.Handle;
        }

        internal void Remove(SoftBodyHandle handle)
        {
            SoftBody body = Get(handle);
            body.Destroyed = true;
            _slots[handle.Index] = null;
            _free.Push(handle.Index);
            int at = _active.IndexOf(body);
            _active[at] = _active[_active.Count - 1];
            _active.RemoveAt(_active.Count - 1);
        }

        internal bool IsLive(SoftBodyHandle handle) =>
            handle.WorldId == _world.Id && handle.Generation != 0 && (uint)handle.Index < (uint)_slots.Count && _slots[handle.Index] is SoftBody b && b.Generation == handle.Generation;

        internal SoftBody Get(SoftBodyHandle handle)
        {
            if (!handle.IsNone && handle.WorldId != _world.Id) throw _world.ForeignHandle(handle.ToString(), handle.WorldId);
            if (!IsLive(handle))
                throw new StaleHandleException(handle.IsNone
                    ? "The soft body handle is None."
                    : $"{handle} does not name a live soft body: it was destroyed, or was never issued by this world.");
            return _slots[handle.Index]!;
        }

        /// <inheritdoc/>
        public void Step(World world, float dt)
        {
            if (_active.Count == 0) return;
            IParallelScheduler? pool = world.ParallelScheduler();

            _coupling.Begin(world, dt);
            for (int k = 0; k < _active.Count; k++) _active[k].BeginStep(dt, _coupling);
            // After BeginStep: a Newton body's substeps depend on whether it touches anything.
            int substeps = 1;
            for (int k = 0; k < _active.Count; k++) substeps = Math.Max(substeps, _active[k].SubstepsFor(dt));
            float h = dt / substeps;
            _coupling.SetSubsteps(substeps);
            _softContacts.FindPairs(_active, world.Gravity.Length(), dt);
            for (int s = 0; s < substeps; s++)
            {
                _coupling.BeginSubstep((s + 1f) / substeps, h);
                for (int k = 0; k < _active.Count; k++) _active[k].Substep(h, _coupling, pool);
                if (_softContacts.PairCount > 0) _softContacts.Solve(h);
            }
            for (int k = 0; k < _active.Count; k++)
            {
                _active[k].EndStep(dt);
                if (_active[k].KeepFinite()) continue;
                DivergenceCount++;
                LastDiverged = _active[k].Handle;
                LastDivergedStep = world.StepIndex;
                Diverged?.Invoke(LastDiverged, LastDivergedStep);
            }
        }

        /// <summary>
        /// Raised (on the stepping thread) for a soft body whose vertices became non-finite or left
        /// the world bounds (±<see cref="Limits.MaxPosition"/> m) in a step, with the step index:
        /// the body was put back at its pose from the start of that step, at rest.
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
