using System;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    internal sealed partial class NarrowPhase
    {
        // Runs every contact's reuse or pair function on the worker pool, as the serial pass
        // would run it with the awake states of the start of the pass (the same tests), before
        // that pass: reuse writes only the contact's own manifolds, a pair function only its
        // result slot, or, when its patches fit the contact's chain of manifolds as it is and
        // neither body can be woken in the pass, the contact's own manifolds (warm starting, the
        // points remembered for reuse). A contact of two bodies that cannot be woken, reused,
        // rewritten or out of reach with no manifolds, is finished there (flags too): the serial
        // pass skips it and lists it afterwards (the solver's order is that of the pair keys, so
        // the order of listing does not matter). The serial pass takes every other answer and
        // does what depends on order (manifold allocation, destroying contacts, waking). A body
        // woken during the pass changes those states; its contacts then run inline (a reuse run
        // again from the stored points writes the same values; a pair function matches
        // impulses by feature id, not by the points reuse moved; no contact of a body that can be
        // woken was rewritten), so the pass computes exactly what the serial one would.
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
        /// place, its manifolds rewritten in place from its pair function (when the chain keeps its
        /// length and neither body can be woken by the serial pass), or the pair function's
        /// reduced patches, in the job's slot <paramref name="k"/>.
        /// </summary>
        public void Precompute(int k, NarrowPhaseJob job, ContactBuffer buffer, ContactPointCache cache)
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
            // Neither body can be woken by the serial pass: a contact with nothing order-
            // dependent left to do (no manifold to allocate or free, no contact to destroy) is
            // finished here, flags included, and only listed by the serial pass.
            bool settled = CannotWake(ct.BodyA, awakeA) && CannotWake(ct.BodyB, awakeB);
            _slot[c] = k + 1;
            if (parted || !InReach(shapeA, shapeB, false))
            {
                job.SetApart(k, awakeA, awakeB, parted);
                if (!parted && settled && ct.FirstManifold < 0) Finish(ref ct, k, job);
                return;
            }
            float speculative = _in.SpeculativeBase + MotionBound(shapeA, shapeB);
            Pose poseA = StepShapePose(shapeA), poseB = StepShapePose(shapeB);
            if (ReuseEnabled && CanReuseManifolds(ct, speculative, poseA, poseB)
                && ReuseManifolds(ref ct, speculative, poseA, poseB, out int touching, out float deepest))
            {
                job.SetReused(k, awakeA, awakeB, speculative, touching, deepest);
                if (settled) Finish(ref ct, k, job);
            }
            else
            {
                buffer.Clear(speculative);
                CollisionTable.Collide(_in.Shapes.Geometry[shapeA], poseA, _in.Shapes.Geometry[shapeB], poseB, buffer);
                buffer.Reduce();
                int patches = Math.Min(buffer.PatchCount, ContactGraph.MaxManifoldsPerPair);
                if (patches > 0 && patches == ct.ManifoldCount && settled)
                {
                    // What the serial pass does after the pair function, short of the order-
                    // dependent parts (no manifold is allocated or freed here).
                    cache.Capture(g, ct.FirstManifold);
                    WriteManifolds(ref ct, buffer, cache);
                    Measure(ct, out int points, out float depth);
                    FinishRewrite(ref ct, speculative, poseA, poseB);
                    job.SetWritten(k, awakeA, awakeB, speculative, points, depth);
                    Finish(ref ct, k, job);
                }
                else job.SetCollided(k, awakeA, awakeB, speculative, buffer);
            }
        }

        // The flags the serial pass would leave on a contact it updated; the slot marked finished.
        // Written only when they change (most were set so last step): a line this worker writes
        // is one the stepping thread must fetch back from it when it next reads the contact.
        static void Finish(ref Contact ct, int k, NarrowPhaseJob job)
        {
            ContactFlags flags = (ct.Flags & ~ContactFlags.Overlapping) | ContactFlags.Updated;
            if (flags != ct.Flags) ct.Flags = flags;
            job.Finish(k, ct.Key);
        }

        // True when the parallel pass finished contact c (the serial pass skips it).
        bool FinishedInParallel(int c) => c < _slot.Length && _slot[c] != 0 && _job!.Finished(_slot[c] - 1);

        // True when the serial pass cannot wake the body (it is awake, or static): a contact's
        // answer computed with its awake state is then the answer the serial pass takes.
        bool CannotWake(int body, bool awake) => awake || _in.Bodies.Type[body] == BodyType.Static;

        // The result index of contact c's precomputed answer, or -1 (none, or computed with
        // awake states that changed since).
        int TakeParallelResult(int c, bool awakeA, bool awakeB)
        {
            if (c >= _slot.Length || _slot[c] == 0) return -1;
            int i = _slot[c] - 1;
            _slot[c] = 0;
            return _job!.Matches(i, awakeA, awakeB) ? i : -1;
        }

        // Lists the contacts the parallel pass finished (in slot order: the solver's order is
        // the keys', and keys are unique) with their share of the step's figures, and clears
        // the slots.
        void TakeFinishedResults()
        {
            NarrowPhaseJob job = _job!;
            for (int i = 0; i < job.Count; i++)
            {
                int c = job.Contact(i);
                _slot[c] = 0;
                if (!job.Finished(i) || !job.Listed(i)) continue;
                AddToSort(job.Key(i), c);
                job.Reused(i, out int touching, out float deepest);
                Count(touching, deepest);
                if (job.Written(i)) ParallelRewrites++;
                else ReusedPairs++;
            }
            job.Count = 0;
        }
    }
}
