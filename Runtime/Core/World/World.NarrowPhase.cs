using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        // Narrow-phase state: the persistent contacts and manifolds, and this step's list for the solver.
        internal ContactGraph ContactGraph = new ContactGraph();
        /// <summary>This step's manifolds for the solver (see <see cref="ContactSet"/>).</summary>
        internal readonly ContactSet Contacts = new ContactSet();
        readonly ContactBuffer _contactBuffer = new ContactBuffer();
        readonly ContactPointCache _pointCache = new ContactPointCache();
        ulong[] _sortKeys = new ulong[64];
        int[] _sortItems = new int[64];
        int _sortCount;
        readonly KeyOrder _contactOrder = new KeyOrder();
        // Touching points and deepest penetration of this step's listed manifolds, measured
        // where each manifold is written (its points are in cache there).
        int _stepTouching;
        float _stepMaxPenetration;
        bool _anyWoken;
        // Parallel narrow phase (Settings.Threads > 1): the candidates' pair functions run on
        // the worker pool first; per contact slot, the candidate index + 1 (0: none).
        NarrowPhaseJob? _narrowJob;
        int[] _narrowSlot = Array.Empty<int>();
        // Fewer candidates than this are not worth a trip through the pool.
        const int MinParallelPairs = 32;

        /// <summary>Steps whose narrow phase ran its pair functions on the worker pool (for tests).</summary>
        internal long ParallelNarrowPhaseSteps;

        /// <summary>
        /// <see cref="StepStage.NarrowPhase"/>: runs the pair functions of every contact with an
        /// awake body (on the worker pool first when there are enough), carries impulses over by
        /// feature id or reuses last step's manifolds, and lists the manifolds for the solver in
        /// shape-pair order (<see cref="Contacts"/>). Reads: shape geometry, this step's shape
        /// poses, bounds and motion bounds, fat boxes, body velocities and awake flags. Writes:
        /// the contact graph (manifolds, flags, destroyed contacts), <see cref="Contacts"/>,
        /// <see cref="StatContactCount"/> and <see cref="StatMaxPenetration"/>.
        /// Two things of later stages happen here, because moving them would change results or
        /// lose data: a sleeping dynamic body that a new manifold touches wakes at once, so that
        /// its own pairs with other sleepers run in this same stage (the second pass below; the
        /// Islands stage then only wakes through existing constraints); and a touching contact
        /// whose fat boxes parted records its End event before it is destroyed (its shapes and
        /// points are gone by SleepAndEvents, which publishes it in pair order).
        /// </summary>
        void NarrowPhase(float dt)
        {
            Contacts.Clear();
            _anyWoken = false;
            _sortCount = 0;
            _stepTouching = 0;
            _stepMaxPenetration = 0;
            _reuseCosHalfAngle = MathF.Cos(0.5f * _settings.ManifoldReuseAngle);
            ContactGraph g = ContactGraph;
            bool parallel = _settings.Threads > 1 && CollideInParallel(dt);
            int k = 0;
            while (k < g.DenseCount)
            {
                int c = g.Dense[k];
                if (UpdateContact(c, dt)) k++;
            }
            if (parallel) ForgetNarrowResults();
            // Bodies woken by a contact: their pairs with other sleepers were skipped above.
            while (_anyWoken)
            {
                _anyWoken = false;
                k = 0;
                while (k < g.DenseCount)
                {
                    int c = g.Dense[k];
                    ref Contact ct = ref g.Contacts[c];
                    bool pending = (ct.Flags & ContactFlags.Updated) == 0 && (Bodies.Awake[ct.BodyA] || Bodies.Awake[ct.BodyB]);
                    if (!pending || UpdateContact(c, dt)) k++;
                }
            }
            GatherManifolds();
        }

        // Returns false when the contact was destroyed (its dense slot now holds another).
        bool UpdateContact(int c, float dt)
        {
            ContactGraph g = ContactGraph;
            ref Contact ct = ref g.Contacts[c];
            ct.Flags &= ~(ContactFlags.Updated | ContactFlags.Overlapping);
            int bodyA = ct.BodyA, bodyB = ct.BodyB;
            bool awakeA = Bodies.Awake[bodyA], awakeB = Bodies.Awake[bodyB];
            if (!awakeA && !awakeB) return true;

            int shapeA = ct.ShapeA, shapeB = ct.ShapeB;
            if (FatBoxesParted(shapeA, shapeB))
            {
                if ((ct.Flags & ContactFlags.Touching) != 0) RecordStepEnd(c);
                g.Destroy(c);
                return false;
            }
            ct.Flags |= ContactFlags.Updated;

            bool sensor = (ct.Flags & ContactFlags.Sensor) != 0;
            ContactBuffer buffer = _contactBuffer;
            float speculative = 0;
            bool reduced = false;
            bool reuse = !sensor && ManifoldReuseEnabled;
            Pose poseA = default, poseB = default;
            if (InReach(shapeA, shapeB, sensor))
            {
                if (!sensor) speculative = SpeculativeBase + MotionBound(shapeA, shapeB, dt);
                if (reuse)
                {
                    poseA = StepShapePose(shapeA);
                    poseB = StepShapePose(shapeB);
                    if (CanReuseManifolds(ct, speculative, poseA, poseB) && ReuseManifolds(ref ct, speculative, poseA, poseB))
                    {
                        TakeNarrowResult(c, awakeA, awakeB);
                        AddToSort(ct.Key, c);
                        WakeSleeper(bodyA, awakeA);
                        WakeSleeper(bodyB, awakeB);
                        return true;
                    }
                }
                int slot = TakeNarrowResult(c, awakeA, awakeB);
                if (slot >= 0)
                {
                    _narrowJob!.Restore(slot, buffer, speculative);
                    reduced = true;
                }
                else
                {
                    buffer.Clear(speculative);
                    if (!reuse)
                    {
                        poseA = StepShapePose(shapeA);
                        poseB = StepShapePose(shapeB);
                    }
                    CollisionTable.Collide(Shapes.Geometry[shapeA], poseA, Shapes.Geometry[shapeB], poseB, buffer);
                }
            }
            else
            {
                if (ct.FirstManifold < 0) return true;
                buffer.Clear(0);
            }
            if (sensor)
            {
                if (buffer.PointCount > 0) ct.Flags |= ContactFlags.Overlapping;
                return true;
            }
            if (!reduced) buffer.Reduce();
            WriteManifolds(ref ct, buffer);
            if (ct.ManifoldCount > 0)
            {
                AddToSort(ct.Key, c);
                Measure(ct);
            }
            // A pair that can approach by more than the reuse bound's half margin in this step
            // will have moved too far to reuse next step: storing its points would be wasted.
            if (reuse && ct.ManifoldCount > 0 && speculative <= 1.5f * SpeculativeBase)
                RememberManifolds(ref ct, speculative, poseA, poseB);
            else ct.Flags &= ~ContactFlags.Reusable;

            if (ct.ManifoldCount > 0)
            {
                WakeSleeper(bodyA, awakeA);
                WakeSleeper(bodyB, awakeB);
            }
            return true;
        }

        // The pair-liveness checks, the same for the serial pass and the parallel candidates.
        // Fat boxes only change when a proxy moves: whether they parted is checked only then.
        bool FatBoxesParted(int shapeA, int shapeB) =>
            (_fatBoxStep[shapeA] == _stepIndex || _fatBoxStep[shapeB] == _stepIndex) &&
            !_broadPhase.FatAabb(Shapes.ProxyId[shapeA]).Overlaps(_broadPhase.FatAabb(Shapes.ProxyId[shapeB]));

        // Tight bounds farther apart than any speculative distance the pair could have (each
        // shape's own motion bound; none for a sensor) cannot give a point.
        bool InReach(int shapeA, int shapeB, bool sensor)
        {
            float reach = sensor ? 0 : SpeculativeBase + _shapeMotion[shapeA] + _shapeMotion[shapeB];
            return Shapes.WorldAabb[shapeA].Expanded(reach).Overlaps(Shapes.WorldAabb[shapeB]);
        }

        // A sleeping dynamic body that a listed contact touches wakes (its pairs are then run by
        // the narrow phase's second pass).
        void WakeSleeper(int body, bool awake)
        {
            if (awake || Bodies.Type[body] != BodyType.Dynamic) return;
            Wake(body);
            _anyWoken = true;
        }

        // Lists the contacts whose pair function the serial pass would run with the awake
        // states of the start of the pass (the same tests, read-only) and runs them on the
        // worker pool. A body woken during the pass changes those states; its contacts then
        // run inline, so the pass computes exactly what the serial one would.
        bool CollideInParallel(float dt)
        {
            ContactGraph g = ContactGraph;
            if (_narrowSlot.Length < g.Contacts.Length) _narrowSlot = new int[g.Contacts.Length];
            NarrowPhaseJob job = NarrowJob();
            job.Count = 0;
            job.Dt = dt;
            bool reuse = ManifoldReuseEnabled;
            for (int k = 0; k < g.DenseCount; k++)
            {
                int c = g.Dense[k];
                ref Contact ct = ref g.Contacts[c];
                bool awakeA = Bodies.Awake[ct.BodyA], awakeB = Bodies.Awake[ct.BodyB];
                if (!awakeA && !awakeB || (ct.Flags & ContactFlags.Sensor) != 0) continue;
                int shapeA = ct.ShapeA, shapeB = ct.ShapeB;
                if (FatBoxesParted(shapeA, shapeB) || !InReach(shapeA, shapeB, false)) continue;
                // The serial pass will most likely carry these manifolds over (it decides again).
                if (reuse && CanReuseManifolds(ct, SpeculativeBase + MotionBound(shapeA, shapeB, dt), StepShapePose(shapeA), StepShapePose(shapeB)))
                    continue;
                job.Add(c, awakeA, awakeB);
            }
            if (job.Count < MinParallelPairs)
            {
                job.Count = 0;
                return false;
            }
            for (int i = 0; i < job.Count; i++) _narrowSlot[job.Contact(i)] = i + 1;
            job.Run(SolverThreads());
            ParallelNarrowPhaseSteps++;
            return true;
        }

        // The parallel narrow phase's job, made on first use with the capacity World.Reserve asked for.
        NarrowPhaseJob NarrowJob()
        {
            if (_narrowJob == null)
            {
                _narrowJob = new NarrowPhaseJob(this);
                _narrowJob.Reserve(_reservedPairs, _settings.Threads);
            }
            return _narrowJob;
        }

        // The pair function of contact c as the serial pass runs it (pure: reads poses,
        // velocities and bounds, writes only the buffer), for the worker threads.
        internal void CollideContact(int c, float dt, ContactBuffer buffer)
        {
            ref Contact ct = ref ContactGraph.Contacts[c];
            int shapeA = ct.ShapeA, shapeB = ct.ShapeB;
            buffer.Clear(SpeculativeBase + MotionBound(shapeA, shapeB, dt));
            CollisionTable.Collide(Shapes.Geometry[shapeA], StepShapePose(shapeA), Shapes.Geometry[shapeB], StepShapePose(shapeB), buffer);
        }

        // The candidate index of contact c's precomputed result, or -1 (none, or computed
        // with awake states that changed since).
        int TakeNarrowResult(int c, bool awakeA, bool awakeB)
        {
            if (c >= _narrowSlot.Length || _narrowSlot[c] == 0) return -1;
            int i = _narrowSlot[c] - 1;
            _narrowSlot[c] = 0;
            return _narrowJob!.Matches(i, awakeA, awakeB) ? i : -1;
        }

        void ForgetNarrowResults()
        {
            NarrowPhaseJob job = _narrowJob!;
            for (int i = 0; i < job.Count; i++) _narrowSlot[job.Contact(i)] = 0;
            job.Count = 0;
        }

        // How far the two shapes can approach each other in the step: relative linear motion
        // plus each body's rotation swinging its farthest point.
        float MotionBound(int shapeA, int shapeB, float dt)
        {
            int a = Shapes.Body[shapeA], b = Shapes.Body[shapeB];
            BodyStorage s = Bodies;
            Vector3 va = s.Awake[a] ? s.LinearVelocity[a] : Vector3.Zero;
            Vector3 vb = s.Awake[b] ? s.LinearVelocity[b] : Vector3.Zero;
            float bound = (va - vb).Length();
            if (s.Awake[a]) bound += s.AngularVelocity[a].Length() * Reach(Shapes.WorldAabb[shapeA], s.Center[a]);
            if (s.Awake[b]) bound += s.AngularVelocity[b].Length() * Reach(Shapes.WorldAabb[shapeB], s.Center[b]);
            return bound * dt;
        }

        // Rewrites a contact's manifold chain from the buffer; points whose feature id
        // existed last step inherit its accumulated impulses (warm starting).
        void WriteManifolds(ref Contact ct, ContactBuffer buffer)
        {
            ContactGraph g = ContactGraph;
            ContactPointCache cache = _pointCache;
            cache.Capture(g, ct.FirstManifold);

            // Resize the chain to the number of patches.
            int patches = Math.Min(buffer.PatchCount, ContactGraph.MaxManifoldsPerPair);
            int first = ct.FirstManifold;
            if (patches == 0) { g.FreeManifolds(ref ct); return; }
            if (first < 0) first = ct.FirstManifold = g.AllocateManifold();
            int m = first;
            for (int p = 1; p < patches; p++)
            {
                if (g.ManifoldNext[m] < 0)
                {
                    // Allocate first: the pool may grow, and the link must go into the new array.
                    int next = g.AllocateManifold();
                    g.ManifoldNext[m] = next;
                }
                m = g.ManifoldNext[m];
            }
            if (g.ManifoldNext[m] >= 0)
            {
                var tail = new Contact { FirstManifold = g.ManifoldNext[m] };
                g.FreeManifolds(ref tail);
                g.ManifoldNext[m] = -1;
            }
            ct.ManifoldCount = patches;

            ShapeStorage s = Shapes;
            int sa = ct.ShapeA, sb = ct.ShapeB;
            float friction = Combine.Values(s.Friction[sa], s.FrictionCombine[sa], s.Friction[sb], s.FrictionCombine[sb]);
            float restitution = Combine.Values(s.Restitution[sa], s.RestitutionCombine[sa], s.Restitution[sb], s.RestitutionCombine[sb]);
            Vector3 centerA = Bodies.Center[ct.BodyA], centerB = Bodies.Center[ct.BodyB];
            Vector3 sum = Vector3.Zero;
            int total = 0;
            m = first;
            for (int p = 0; p < patches; p++, m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                int start = buffer.PatchStart[p], count = buffer.PatchPointCount(p);
                mf.BodyA = ct.BodyA;
                mf.BodyB = ct.BodyB;
                mf.ShapeA = sa;
                mf.ShapeB = sb;
                mf.Normal = buffer.PatchNormal[p];
                mf.PointCount = count;
                mf.Friction = friction;
                mf.Restitution = restitution;
                mf.RollingFriction = 0;
                mf.RollingImpulse = cache.RollingImpulse(p);
                for (int i = 0; i < count; i++)
                {
                    ref ContactPoint cp = ref ContactManifold.Point(ref mf, i);
                    Vector3 x = buffer.Position[start + i];
                    cp.Position = x;
                    cp.AnchorA = x - centerA;
                    cp.AnchorB = x - centerB;
                    cp.Separation = buffer.Separation[start + i];
                    cp.FeatureId = buffer.Id[start + i];
                    cp.RelativeNormalVelocity = 0;
                    cp.AppliedImpulse = 0; // the solver sets it if it runs this step
                    cp.Persisted = cache.TryTake(cp.FeatureId, out cp.NormalImpulse, out cp.TangentImpulse1, out cp.TangentImpulse2);
                    sum += x;
                    total++;
                }
            }
            if (total > 0)
            {
                Vector3 at = sum / total;
                ct.RelativeVelocity = PointVelocity(ct.BodyB, at) - PointVelocity(ct.BodyA, at);
            }
        }

        Vector3 PointVelocity(int body, Vector3 at) =>
            Bodies.LinearVelocity[body] + Vector3.Cross(Bodies.AngularVelocity[body], at - Bodies.Center[body]);

        // A contact with manifolds this step, to be listed for the solver (each contact is
        // updated at most once per step, so at most once here).
        void AddToSort(ulong key, int contact)
        {
            if (_sortCount == _sortKeys.Length)
            {
                Array.Resize(ref _sortKeys, 2 * _sortCount);
                Array.Resize(ref _sortItems, 2 * _sortCount);
            }
            _sortKeys[_sortCount] = key;
            _sortItems[_sortCount] = contact;
            _sortCount++;
        }

        // Counts the touching points and the deepest penetration of a contact listed this step.
        void Measure(in Contact ct)
        {
            ContactGraph g = ContactGraph;
            float slop = _settings.LinearSlop;
            for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                for (int i = 0; i < mf.PointCount; i++)
                {
                    float sep = ContactManifold.Point(ref mf, i).Separation;
                    if (sep <= slop) _stepTouching++;
                    if (-sep > _stepMaxPenetration) _stepMaxPenetration = -sep;
                }
            }
        }

        // Lists the manifolds of this step's updated, non-sensor contacts for the solver,
        // ordered by shape pair, and publishes the contact count and penetration.
        void GatherManifolds()
        {
            ContactGraph g = ContactGraph;
            int n = _sortCount;
            _contactOrder.Sort(_sortKeys, _sortItems, n);
            for (int k = 0; k < n; k++)
            {
                ref Contact ct = ref g.Contacts[_sortItems[k]];
                for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
                    Contacts.Add(m);
            }
            Contacts.Pool = g.Manifolds;
            StatContactCount = _stepTouching;
            if (_stepMaxPenetration > StatMaxPenetration) StatMaxPenetration = _stepMaxPenetration;
        }

    }
}
