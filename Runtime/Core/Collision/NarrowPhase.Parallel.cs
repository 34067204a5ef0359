using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    internal sealed partial class NarrowPhase
    {
        // Runs every contact's reuse or pair function on the worker pool, as the serial pass
        // would run it with the awake states of the start of the pass (the same tests), before
        // that pass: reuse writes only the contact's own manifolds, a pair function only its
        // result slot. The serial pass then takes each answer and does what depends on order
        // (manifold allocation, warm starting, waking, sorting, the step's figures). A body woken
        // during the pass changes those states; its contacts then run inline (a reuse run again
        // from the stored points writes the same values; a pair function matches impulses by
        // feature id, not by the points reuse moved), so the pass computes exactly what the
        // serial one would.
        bool CollideInParallel<THost>(ref THost host) where THost : struct, INarrowPhaseHost
        {
            ContactGraph g = Graph;
            if (g.DenseCount < MinParallelPairs) return false;
            if (_slot.Length < g.Contacts.Length) _slot = new int[g.Contacts.Length];
            NarrowPhaseJob job = Job();
            job.Run(g.DenseCount, host.Workers());
            ParallelSteps++;
            return true;
        }

        /// <summary>
        /// The parallel pass for the contact at dense index <paramref name="k"/> (on a worker):
        /// nothing for a contact the serial pass skips (both bodies asleep, a sensor); whether
        /// its fat boxes parted or its shapes are out of reach; else its manifolds reused in
        /// place or its pair function's reduced patches, in the job's slot <paramref name="k"/>.
        /// </summary>
        public void Precompute(int k, NarrowPhaseJob job, ContactBuffer buffer)
        {
            ContactGraph g = Graph;
            int c = g.Dense[k];
            ref Contact ct = ref g.Contacts[c];
            job.Clear(k, c);
            BodyStorage bodies = _in.Bodies;
            bool awakeA = bodies.Awake[ct.BodyA], awakeB = bodies.Awake[ct.BodyB];
            if (!awakeA && !awakeB || (ct.Flags & ContactFlags.Sensor) != 0) return;
            int shapeA = ct.ShapeA, shapeB = ct.ShapeB;
            bool parted = FatBoxesParted(shapeA, shapeB);
            if (parted || !InReach(shapeA, shapeB, false))
            {
                job.SetApart(k, awakeA, awakeB, parted);
                _slot[c] = k + 1;
                return;
            }
            float speculative = _in.SpeculativeBase + MotionBound(shapeA, shapeB);
            Pose poseA = StepShapePose(shapeA), poseB = StepShapePose(shapeB);
            if (ReuseEnabled && CanReuseManifolds(ct, speculative, poseA, poseB)
                && ReuseManifolds(ref ct, speculative, poseA, poseB, out int touching, out float deepest))
            {
                job.SetReused(k, awakeA, awakeB, speculative, touching, deepest);
            }
            else
            {
                buffer.Clear(speculative);
                CollisionTable.Collide(_in.Shapes.Geometry[shapeA], poseA, _in.Shapes.Geometry[shapeB], poseB, buffer);
                buffer.Reduce();
                job.SetCollided(k, awakeA, awakeB, speculative, buffer);
            }
            _slot[c] = k + 1;
        }

        // The result index of contact c's precomputed answer, or -1 (none, or computed with
        // awake states that changed since).
        int TakeParallelResult(int c, bool awakeA, bool awakeB)
        {
            if (c >= _slot.Length || _slot[c] == 0) return -1;
            int i = _slot[c] - 1;
            _slot[c] = 0;
            return _job!.Matches(i, awakeA, awakeB) ? i : -1;
        }

        void ForgetParallelResults()
        {
            NarrowPhaseJob job = _job!;
            for (int i = 0; i < job.Count; i++) _slot[job.Contact(i)] = 0;
            job.Count = 0;
        }
    }
}
