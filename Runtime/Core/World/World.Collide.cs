using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        // Collision state. The margin policy is written down in CollisionMargins.
        internal BroadPhase BroadPhase = new BroadPhase();
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
        // Per shape slot: how far the shape can move in this step (refreshed for awake moving
        // shapes by the broad phase; 0 for static ones), and the step its fat box last changed.
        float[] _shapeMotion = Array.Empty<float>();
        // Per shape slot: the farthest its geometry reaches from its own origin (manifold reuse
        // bounds how far a rotation can move a shape's points with it).
        float[] _shapeRadius = Array.Empty<float>();
        // Per shape slot: its world pose as the broad phase computed it this step (stamped with
        // the step index), so the narrow phase does not rebuild it for every pair.
        Pose[] _shapePose = Array.Empty<Pose>();
        long[] _shapePoseStep = Array.Empty<long>();
        long[] _fatBoxStep = Array.Empty<long>();
        // Parallel narrow phase (Settings.Threads > 1): the candidates' pair functions run on
        // the worker pool first; per contact slot, the candidate index + 1 (0: none).
        NarrowPhaseJob? _narrowJob;
        int[] _narrowSlot = Array.Empty<int>();
        // Fewer candidates than this are not worth a trip through the pool.
        const int MinParallelPairs = 32;

        /// <summary>Steps whose narrow phase ran its pair functions on the worker pool (for tests).</summary>
        internal long ParallelNarrowPhaseSteps;

        float SpeculativeBase => CollisionMargins.SpeculativeDistance(_settings.LinearSlop);

        void OnShapeAdded(int shape)
        {
            ContactGraph.EnsureShapeCapacity(Shapes.SlotCount);
            if (_shapeMotion.Length < Shapes.SlotCount)
            {
                int n = Math.Max(Shapes.SlotCount, 2 * _shapeMotion.Length);
                Array.Resize(ref _shapeMotion, n);
                Array.Resize(ref _shapeRadius, n);
                Array.Resize(ref _shapePose, n);
                Array.Resize(ref _shapePoseStep, n);
                Array.Resize(ref _fatBoxStep, n);
            }
            _shapeMotion[shape] = 0;
            _shapePoseStep[shape] = -1;
            Aabb local = Shapes.Geometry[shape].ComputeAabb(Pose.Identity);
            _shapeRadius[shape] = local.Center.Length() + local.Extents.Length();
            _fatBoxStep[shape] = _stepIndex;
            int b = Shapes.Body[shape];
            bool isStatic = Bodies.Type[b] == BodyType.Static;
            Aabb fat = Shapes.WorldAabb[shape].Expanded(CollisionMargins.AabbMargin + SpeculativeBase);
            Shapes.ProxyId[shape] = BroadPhase.CreateProxy(fat, shape, isStatic);
            OnCcdShapeAdded(b);
        }

        void OnShapeRemoved(int shape)
        {
            int edge = ContactGraph.FirstEdge(shape);
            while (edge >= 0)
            {
                int next = ContactGraph.NextEdge(edge);
                int c = edge >> 1;
                if ((ContactGraph.Contacts[c].Flags & ContactFlags.Touching) != 0)
                    RecordRemovalEnd(c);
                ContactGraph.Destroy(c);
                edge = next;
            }
            BroadPhase.DestroyProxy(Shapes.ProxyId[shape]);
            Shapes.ProxyId[shape] = -1;
            OnCcdShapeRemoved(Shapes.Body[shape]);
            ForgetIgnoredPairs(shape);
        }

        // The shape's world pose: this step's broad-phase copy for awake moving shapes, computed
        // afresh for the others (static, sleeping).
        Pose StepShapePose(int shape) => _shapePoseStep[shape] == _stepIndex ? _shapePose[shape] : ShapeWorldPose(shape);

        // Refreshes the bounds of awake moving shapes, swept over their predicted motion in
        // this step, moves the proxies whose swept bounds left their fat boxes (or whose fat
        // boxes became far too loose), then finds the new pairs.
        void UpdateBroadPhase(float dt)
        {
            ShapeStorage s = Shapes;
            BodyStorage b = Bodies;
            float grow = SpeculativeBase;
            for (int k = 0; k < s.ActiveCount; k++)
            {
                int i = s.Active[k];
                int body = s.Body[i];
                if (b.Type[body] == BodyType.Static || !b.Awake[body]) continue;
                Pose pose = ShapeWorldPose(i);
                _shapePose[i] = pose;
                _shapePoseStep[i] = _stepIndex;
                Aabb tight = s.Geometry[i].ComputeAabb(pose);
                s.WorldAabb[i] = tight;
                float angular = b.AngularVelocity[body].Length() * dt * Reach(tight, b.Center[body]);
                Aabb swept = tight.Expanded(grow + angular);
                Vector3 move = b.LinearVelocity[body] * dt;
                _shapeMotion[i] = move.Length() + angular;
                swept = new Aabb(swept.Min + Vector3.Min(move, Vector3.Zero), swept.Max + Vector3.Max(move, Vector3.Zero));
                if (RefitProxy(s.ProxyId[i], swept)) _fatBoxStep[i] = _stepIndex;
            }
            BroadPhase.UpdatePairs(this);
        }

        // True when the proxy got a new fat box.
        bool RefitProxy(int proxy, in Aabb swept)
        {
            ref readonly Aabb fat = ref BroadPhase.FatAabb(proxy);
            Aabb wanted = swept.Expanded(CollisionMargins.AabbMargin);
            // A fat box four times the area it needs came from a fast phase that ended.
            if (fat.Contains(swept) && fat.SurfaceArea <= 4f * wanted.SurfaceArea) return false;
            BroadPhase.MoveProxy(proxy, wanted);
            return true;
        }

        // The farthest a shape's bounds reach from its body's centre of mass.
        static float Reach(in Aabb box, Vector3 center) => Vector3.Distance(box.Center, center) + box.Extents.Length();

        /// <summary>
        /// The pair filter: called by the broad phase for each new overlap of fat boxes.
        /// Creates a contact when the shapes are on different bodies, at least one of which is
        /// dynamic (or, for a sensor, not static), their layers accept each other, a pair
        /// function exists and the pair is not known yet.
        /// </summary>
        internal void AddPair(int shapeA, int shapeB)
        {
            ShapeStorage s = Shapes;
            int bodyA = s.Body[shapeA], bodyB = s.Body[shapeB];
            if (bodyA == bodyB) return;
            bool sensor = s.IsSensor[shapeA] || s.IsSensor[shapeB];
            BodyType ta = Bodies.Type[bodyA], tb = Bodies.Type[bodyB];
            if (sensor ? ta == BodyType.Static && tb == BodyType.Static : ta != BodyType.Dynamic && tb != BodyType.Dynamic) return;
            if ((s.CollidesWith[shapeA] & (1u << s.Layer[shapeB])) == 0 || (s.CollidesWith[shapeB] & (1u << s.Layer[shapeA])) == 0) return;
            if (!sensor && JointBlocksCollision(bodyA, bodyB)) return;
            if (IgnoresPair(shapeA, shapeB)) return;
            ShapeType ka = s.Geometry[shapeA].Type, kb = s.Geometry[shapeB].Type;
            if (!CollisionTable.Has(ka, kb)) return;
            if (ContactGraph.Find(shapeA, shapeB) >= 0) return;
            // Shape A has the lower type (the table's order), ties broken by slot.
            if (kb < ka || (kb == ka && shapeB < shapeA))
            {
                (shapeA, shapeB) = (shapeB, shapeA);
                (bodyA, bodyB) = (bodyB, bodyA);
            }
            ContactGraph.Create(shapeA, shapeB, bodyA, bodyB, sensor);
        }

        // Runs the pair functions of every contact with an awake body, carries impulses over
        // by feature id, wakes sleeping bodies that an awake one touches, and lists the
        // manifolds for the solver in shape-pair order.
        void UpdateContacts(float dt)
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
            // Fat boxes only change when a proxy moves: check whether they parted only then.
            if ((_fatBoxStep[shapeA] == _stepIndex || _fatBoxStep[shapeB] == _stepIndex) &&
                !BroadPhase.FatAabb(Shapes.ProxyId[shapeA]).Overlaps(BroadPhase.FatAabb(Shapes.ProxyId[shapeB])))
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
            // Tight bounds farther apart than any speculative distance the pair could have
            // (each shape's own motion bound): no point can come out.
            float reach = sensor ? 0 : SpeculativeBase + _shapeMotion[shapeA] + _shapeMotion[shapeB];
            bool reuse = !sensor && ManifoldReuseEnabled;
            Pose poseA = default, poseB = default;
            if (Shapes.WorldAabb[shapeA].Expanded(reach).Overlaps(Shapes.WorldAabb[shapeB]))
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

        // A sleeping dynamic body that a listed contact touches wakes (its pairs are then run by
        // UpdateContacts' second pass).
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
            NarrowPhaseJob job = _narrowJob ??= new NarrowPhaseJob(this);
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
                if ((_fatBoxStep[shapeA] == _stepIndex || _fatBoxStep[shapeB] == _stepIndex) &&
                    !BroadPhase.FatAabb(Shapes.ProxyId[shapeA]).Overlaps(BroadPhase.FatAabb(Shapes.ProxyId[shapeB])))
                    continue;
                float reach = SpeculativeBase + _shapeMotion[shapeA] + _shapeMotion[shapeB];
                if (!Shapes.WorldAabb[shapeA].Expanded(reach).Overlaps(Shapes.WorldAabb[shapeB])) continue;
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
