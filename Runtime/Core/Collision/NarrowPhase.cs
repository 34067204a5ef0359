using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The narrow phase (<see cref="StepStage.NarrowPhase"/>) and the state it owns: the
    /// persistent pairs and their manifolds (<see cref="Graph"/>), this step's list for the
    /// solver (<see cref="Contacts"/>), manifold reuse (NarrowPhase.Reuse.cs) and the parallel
    /// pair functions (<see cref="NarrowPhaseJob"/>). It reads the rest of the world only
    /// through <see cref="NarrowPhaseInput"/> and asks it only through
    /// <see cref="INarrowPhaseHost"/> (waking a body, recording an End event).
    /// </summary>
    internal sealed partial class NarrowPhase
    {
        /// <summary>The persistent contacts (pairs of shapes whose fat boxes overlap) and their manifolds.</summary>
        public ContactGraph Graph = new ContactGraph();
        /// <summary>This step's manifolds for the solver (see <see cref="ContactSet"/>).</summary>
        public readonly ContactSet Contacts = new ContactSet();

        /// <summary>Touching points of this step's listed manifolds.</summary>
        public int Touching;
        /// <summary>The deepest penetration of this step's listed manifolds, metres.</summary>
        public float MaxPenetration;
        /// <summary>Contacts whose manifolds were carried over instead of colliding again this step.</summary>
        public int ReusedPairs;
        /// <summary>Steps whose narrow phase ran its pair functions on the worker pool (for tests).</summary>
        public long ParallelSteps;
        /// <summary>Contacts whose manifolds the worker pool rewrote in place (for tests).</summary>
        public long ParallelRewrites;

        NarrowPhaseInput _in;
        readonly ContactBuffer _contactBuffer = new ContactBuffer();
        readonly ContactPointCache _pointCache = new ContactPointCache();
        ulong[] _sortKeys = new ulong[64];
        int[] _sortItems = new int[64];
        int _sortCount;
        readonly KeyOrder _contactOrder = new KeyOrder();
        bool _anyWoken;
        // Parallel narrow phase (Threads > 1): every contact's reuse or pair function runs on
        // the worker pool first; per contact slot, its result's index + 1 (0: none).
        NarrowPhaseJob? _job;
        // The largest pair count and thread count ReserveParallel was given.
        int _reservedPairs, _reservedThreads;
        int[] _slot = Array.Empty<int>();
        // Fewer contacts than this are not worth a trip through the pool.
        const int MinParallelPairs = 64;

        /// <summary>
        /// Runs the pair functions of every contact with an awake body (on the worker pool first
        /// when there are enough), carries impulses over by feature id or reuses last step's
        /// manifolds, and lists the manifolds for the solver in shape-pair order
        /// (<see cref="Contacts"/>). Writes the graph (manifolds, flags, destroyed contacts),
        /// <see cref="Contacts"/>, <see cref="Touching"/>, <see cref="MaxPenetration"/> and
        /// <see cref="ReusedPairs"/>.
        /// Two things of later stages happen here, because moving them would change results or
        /// lose data: a sleeping dynamic body that a new manifold touches wakes at once
        /// (<see cref="INarrowPhaseHost.Wake"/>), so that its own pairs with other sleepers run in
        /// this same stage (the second pass below: deciding the wake in the Islands stage would
        /// leave those pairs without manifolds for one step, which changes results; the Islands
        /// stage then only wakes through existing constraints); and a touching contact whose fat
        /// boxes parted records its End event before it is destroyed
        /// (<see cref="INarrowPhaseHost.ContactEnded"/>: its shapes and points are gone by
        /// SleepAndEvents, which publishes it in pair order).
        /// </summary>
        public void Run<THost>(in NarrowPhaseInput input, ref THost host) where THost : struct, INarrowPhaseHost
        {
            _in = input;
            Contacts.Clear();
            _anyWoken = false;
            _sortCount = 0;
            Touching = 0;
            MaxPenetration = 0;
            ReusedPairs = 0;
            _reuseCosHalfAngle = MathF.Cos(0.5f * input.ReuseAngle);
            ContactGraph g = Graph;
            bool parallel = input.Threads > 1 && CollideInParallel(ref host);
            int k = 0;
            while (k < g.DenseCount)
            {
                int c = g.Dense[k];
                if ((parallel && FinishedInParallel(c)) || UpdateContact(c, ref host)) k++;
            }
            if (parallel) TakeFinishedResults();
            // Bodies woken by a contact: their pairs with other sleepers were skipped above.
            BodyStorage bodies = input.Bodies;
            while (_anyWoken)
            {
                _anyWoken = false;
                k = 0;
                while (k < g.DenseCount)
                {
                    int c = g.Dense[k];
                    ref Contact ct = ref g.Contacts[c];
                    bool pending = (ct.Flags & ContactFlags.Updated) == 0 && (bodies.Awake[ct.BodyA] || bodies.Awake[ct.BodyB]);
                    if (!pending || UpdateContact(c, ref host)) k++;
                }
            }
            GatherManifolds();
            // The storages may be replaced before the next step (a restored state): keep none.
            _in = default;
        }

        /// <summary>Takes a restored state's graph and step list (the parallel results are dropped).</summary>
        public void Restore(ContactGraph graph, int[] source, int manifoldCount)
        {
            Graph = graph;
            Contacts.Pool = graph.Manifolds;
            Contacts.Source = source;
            Contacts.ManifoldCount = manifoldCount;
            _job = null;
            _slot = Array.Empty<int>();
        }

        /// <summary>Sizes the graph, the step list and the sort for <paramref name="pairs"/> contacts and <paramref name="manifolds"/> manifolds.</summary>
        public void Reserve(int pairs, int manifolds)
        {
            Graph.Reserve(pairs, manifolds);
            Contacts.Reserve(manifolds);
            _contactOrder.Reserve(pairs);
            if (_sortKeys.Length >= pairs) return;
            Array.Resize(ref _sortKeys, pairs);
            Array.Resize(ref _sortItems, pairs);
        }

        /// <summary>
        /// Sizes the parallel pass's candidate slots and per-block buffers for
        /// <paramref name="pairs"/> contacts on <paramref name="threads"/> threads (only with
        /// more than one; the pairs are kept for a job made later, when threads are turned on).
        /// </summary>
        public void ReserveParallel(int pairs, int threads)
        {
            _reservedPairs = Math.Max(_reservedPairs, pairs);
            _reservedThreads = Math.Max(_reservedThreads, threads);
            if (threads <= 1) return;
            Job().Reserve(_reservedPairs, threads);
            if (_slot.Length < Graph.Contacts.Length) _slot = new int[Graph.Contacts.Length];
        }

        // The parallel pass's job, made on first use with the capacity ReserveParallel asked for.
        NarrowPhaseJob Job()
        {
            if (_job == null)
            {
                _job = new NarrowPhaseJob(this);
                if (_reservedThreads > 1) _job.Reserve(_reservedPairs, _reservedThreads);
            }
            return _job;
        }

        // Returns false when the contact was destroyed (its dense slot now holds another).
        bool UpdateContact<THost>(int c, ref THost host) where THost : struct, INarrowPhaseHost
        {
            ContactGraph g = Graph;
            BodyStorage bodies = _in.Bodies;
            ref Contact ct = ref g.Contacts[c];
            ct.Flags &= ~(ContactFlags.Updated | ContactFlags.Overlapping);
            int bodyA = ct.BodyA, bodyB = ct.BodyB;
            bool awakeA = bodies.Awake[bodyA], awakeB = bodies.Awake[bodyB];
            if (!awakeA && !awakeB) return true;

            int shapeA = ct.ShapeA, shapeB = ct.ShapeB;
            // The parallel pass's answer for this contact, if it ran it with the awake states of
            // now (the same inputs, so the same answers the tests below would give).
            int slot = TakeParallelResult(c, awakeA, awakeB);
            NarrowPhaseJob? job = slot >= 0 ? _job : null;
            if (job != null ? job.FoundParted(slot) : FatBoxesParted(shapeA, shapeB))
            {
                if ((ct.Flags & ContactFlags.Touching) != 0) host.ContactEnded(c);
                g.Destroy(c);
                return false;
            }
            ct.Flags |= ContactFlags.Updated;

            bool sensor = (ct.Flags & ContactFlags.Sensor) != 0;
            ContactBuffer buffer = _contactBuffer;
            float speculative = 0;
            bool reduced = false;
            bool reuse = !sensor && ReuseEnabled;
            Pose poseA = default, poseB = default;
            if (job != null ? !job.FoundOutOfReach(slot) : InReach(shapeA, shapeB, sensor))
            {
                if (!sensor) speculative = job != null ? job.Speculative(slot) : _in.SpeculativeBase + MotionBound(shapeA, shapeB);
                if (reuse)
                {
                    poseA = StepShapePose(shapeA);
                    poseB = StepShapePose(shapeB);
                }
                int touching = 0;
                float deepest = 0;
                bool reused = job != null ? job.Reused(slot, out touching, out deepest)
                    : reuse && CanReuseManifolds(ct, speculative, poseA, poseB) && ReuseManifolds(ref ct, speculative, poseA, poseB, out touching, out deepest);
                if (reused)
                {
                    Count(touching, deepest);
                    ReusedPairs++;
                    AddToSort(ct.Key, c);
                    WakeSleeper(bodyA, awakeA, ref host);
                    WakeSleeper(bodyB, awakeB, ref host);
                    return true;
                }
                if (job != null)
                {
                    job.Restore(slot, buffer, speculative);
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
                    CollisionTable.Collide(_in.Shapes.Geometry[shapeA], poseA, _in.Shapes.Geometry[shapeB], poseB, buffer);
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
            _pointCache.Capture(g, ct.FirstManifold);
            ResizeChain(ref ct, buffer);
            WriteManifolds(ref ct, buffer, _pointCache);
            if (ct.ManifoldCount > 0)
            {
                AddToSort(ct.Key, c);
                Measure(ct, out int touching, out float deepest);
                Count(touching, deepest);
            }
            FinishRewrite(ref ct, speculative, poseA, poseB);

            if (ct.ManifoldCount > 0)
            {
                WakeSleeper(bodyA, awakeA, ref host);
                WakeSleeper(bodyB, awakeB, ref host);
            }
            return true;
        }

        // The pair-liveness checks, the same for the serial pass and the parallel candidates.
        // Fat boxes only change when a proxy moves: whether they parted is checked only then.
        bool FatBoxesParted(int shapeA, int shapeB)
        {
            long step = _in.StepIndex;
            return (_in.FatBoxStep[shapeA] == step || _in.FatBoxStep[shapeB] == step) &&
                !_in.BroadPhase.FatAabb(_in.Shapes.ProxyId[shapeA]).Overlaps(_in.BroadPhase.FatAabb(_in.Shapes.ProxyId[shapeB]));
        }

        // Tight bounds farther apart than any speculative distance the pair could have (each
        // shape's own motion bound; none for a sensor) cannot give a point.
        bool InReach(int shapeA, int shapeB, bool sensor)
        {
            float reach = sensor ? 0 : _in.SpeculativeBase + _in.ShapeMotion[shapeA] + _in.ShapeMotion[shapeB];
            return _in.Shapes.WorldAabb[shapeA].Expanded(reach).Overlaps(_in.Shapes.WorldAabb[shapeB]);
        }

        // A sleeping dynamic body that a listed contact touches wakes (its pairs are then run by
        // the second pass).
        void WakeSleeper<THost>(int body, bool awake, ref THost host) where THost : struct, INarrowPhaseHost
        {
            if (awake || _in.Bodies.Type[body] != BodyType.Dynamic) return;
            host.Wake(body);
            _anyWoken = true;
        }

        // The shape's world pose: this step's broad-phase copy for awake moving shapes, computed
        // afresh for the others (static, sleeping).
        Pose StepShapePose(int shape) =>
            _in.ShapePoseStep[shape] == _in.StepIndex ? _in.ShapePose[shape] : _in.Shapes.WorldPose(shape, _in.Bodies);

        // How far the two shapes can approach each other in the step: relative linear motion
        // plus each body's rotation swinging its farthest point.
        float MotionBound(int shapeA, int shapeB)
        {
            ShapeStorage shapes = _in.Shapes;
            BodyStorage s = _in.Bodies;
            int a = shapes.Body[shapeA], b = shapes.Body[shapeB];
            Vector3 va = s.Awake[a] ? s.LinearVelocity[a] : Vector3.Zero;
            Vector3 vb = s.Awake[b] ? s.LinearVelocity[b] : Vector3.Zero;
            float bound = (va - vb).Length();
            if (s.Awake[a]) bound += s.AngularVelocity[a].Length() * CollisionMargins.Reach(shapes.WorldAabb[shapeA], s.Center[a]);
            if (s.Awake[b]) bound += s.AngularVelocity[b].Length() * CollisionMargins.Reach(shapes.WorldAabb[shapeB], s.Center[b]);
            return bound * _in.Dt;
        }
    }
}
