using System;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Sizes the world's per-step buffers for up to <paramref name="bodies"/> bodies (with
        /// one shape each) and <paramref name="contactPairs"/> shape pairs whose fattened
        /// bounds overlap (touching or near: about 4 per box in a pyramid, up to 16 in a dense
        /// pile of tilted boxes while it falls), so that a scene growing into those counts, such as a pile collapsing,
        /// allocates nothing inside <see cref="Step"/>; the buffers otherwise double as counts
        /// first rise (as Jolt's <c>PhysicsSystem.Init</c> limits and Bepu's initial allocation
        /// sizes work). Manifolds are planned for the smaller of the pairs and 4 per body.
        /// Counts already reached are kept; nothing shrinks. With <see cref="WorldSettings.Threads"/>
        /// &gt; 1 it also starts the worker threads and sizes the parallel narrow phase's buffers.
        /// </summary>
        /// <exception cref="ArgumentException">A count is negative or above <see cref="Limits.MaxReserve"/>.</exception>
        public void Reserve(int bodies, int contactPairs)
        {
            if (bodies < 0 || bodies > Limits.MaxReserve) throw new ArgumentException($"bodies must be in 0..{Limits.MaxReserve} (Limits.MaxReserve), got {bodies}.", nameof(bodies));
            if (contactPairs < 0 || contactPairs > Limits.MaxReserve) throw new ArgumentException($"contactPairs must be in 0..{Limits.MaxReserve} (Limits.MaxReserve), got {contactPairs}.", nameof(contactPairs));
            if (_inStep) throw new InvalidOperationException("Reserve cannot be called during Step.");
            // Slots, not live counts: every array below is indexed by slot.
            int slots = Math.Max(bodies, Bodies.SlotCount) + 1;
            int pairs = Math.Max(contactPairs, ContactGraph.Count);
            // Touching pairs (one manifold each when convex; meshes may have up to four, which
            // this does not plan for): a box in a pyramid touches about 3.6 others.
            int manifolds = Math.Max(ContactGraph.Count, Math.Min(pairs, 4 * Math.Max(bodies, 1)));
            _narrowPhase.Reserve(pairs, manifolds);
            _broadPhase.Reserve(Math.Max(bodies, Shapes.SlotCount));
            _eventOrder.Reserve(pairs);
            ReserveEvents(pairs);
            Joints.EnsureBodies(slots);
            _islands.Reserve(slots, manifolds, Joints.ActiveCount);
            _solverContext.Reserve(slots, manifolds, Joints.ActiveCount);
            if (_freeBodies.Length < slots) _freeBodies = new int[slots];
            // With threads, the worker pool and the parallel narrow phase's candidate slots are
            // made now too (the slots grow with the contact count otherwise: about 10 KB per
            // step while a 2k-box pile collapsed on 2 threads). A world that turns threads on
            // later gets them sized from the reserved pairs on first use.
            if (_settings.Threads > 1) ParallelScheduler();
            _narrowPhase.ReserveParallel(pairs, _settings.Threads);
            // New pairs in one step: all of them in the first step, when every proxy is new (a
            // block that still fills is searched on the stepping thread, not lost; 16 bytes a
            // pair against the contact's own 88).
            if (_settings.Threads > 1) (_pairSearch ??= new Collision.PairSearch<PairFilter>()).Reserve(pairs, _settings.Threads);
            if (_solvedInStep.Length < slots) Array.Resize(ref _solvedInStep, slots);
        }

        void ReserveEvents(int pairs)
        {
            if (_stepEvents.Length < pairs)
            {
                Array.Resize(ref _stepEvents, pairs);
                Array.Resize(ref _stepEventKeys, pairs);
                Array.Resize(ref _stepEventOrder, pairs);
            }
            if (_events.Length < pairs) Array.Resize(ref _events, pairs);
        }
    }
}
