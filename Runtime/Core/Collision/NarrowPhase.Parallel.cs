using System;

namespace Fulcrum.Collision
{
    internal sealed partial class NarrowPhase
    {
        // Lists the contacts whose pair function the serial pass would run with the awake
        // states of the start of the pass (the same tests, read-only) and runs them on the
        // worker pool. A body woken during the pass changes those states; its contacts then
        // run inline, so the pass computes exactly what the serial one would.
        bool CollideInParallel<THost>(ref THost host) where THost : struct, INarrowPhaseHost
        {
            ContactGraph g = Graph;
            BodyStorage bodies = _in.Bodies;
            if (_slot.Length < g.Contacts.Length) _slot = new int[g.Contacts.Length];
            NarrowPhaseJob job = Job();
            job.Count = 0;
            bool reuse = ReuseEnabled;
            for (int k = 0; k < g.DenseCount; k++)
            {
                int c = g.Dense[k];
                ref Contact ct = ref g.Contacts[c];
                bool awakeA = bodies.Awake[ct.BodyA], awakeB = bodies.Awake[ct.BodyB];
                if (!awakeA && !awakeB || (ct.Flags & ContactFlags.Sensor) != 0) continue;
                int shapeA = ct.ShapeA, shapeB = ct.ShapeB;
                if (FatBoxesParted(shapeA, shapeB) || !InReach(shapeA, shapeB, false)) continue;
                // The serial pass will most likely carry these manifolds over (it decides again).
                if (reuse && CanReuseManifolds(ct, _in.SpeculativeBase + MotionBound(shapeA, shapeB), StepShapePose(shapeA), StepShapePose(shapeB)))
                    continue;
                job.Add(c, awakeA, awakeB);
            }
            if (job.Count < MinParallelPairs)
            {
                job.Count = 0;
                return false;
            }
            for (int i = 0; i < job.Count; i++) _slot[job.Contact(i)] = i + 1;
            job.Run(host.Workers());
            ParallelSteps++;
            return true;
        }

        /// <summary>
        /// The pair function of contact <paramref name="c"/> as the serial pass runs it (pure:
        /// reads poses, velocities and bounds, writes only the buffer), for the worker threads.
        /// </summary>
        public void CollideContact(int c, ContactBuffer buffer)
        {
            ref Contact ct = ref Graph.Contacts[c];
            int shapeA = ct.ShapeA, shapeB = ct.ShapeB;
            buffer.Clear(_in.SpeculativeBase + MotionBound(shapeA, shapeB));
            CollisionTable.Collide(_in.Shapes.Geometry[shapeA], StepShapePose(shapeA), _in.Shapes.Geometry[shapeB], StepShapePose(shapeB), buffer);
        }

        // The candidate index of contact c's precomputed result, or -1 (none, or computed
        // with awake states that changed since).
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
