using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        // Broad-phase state. The margin policy is written down in CollisionMargins.
        BroadPhase _broadPhase = new BroadPhase();
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
        // Per active shape (index into ShapeStorage.Active) in this step's broad phase: whether its
        // proxy takes a new fat box, and that box. Sized with the shape slots.
        bool[] _refit = Array.Empty<bool>();
        Aabb[] _wantedBox = Array.Empty<Aabb>();
        BoundsJob? _boundsJob;
        // The pair search on the worker pool (made when threads are first used).
        PairSearch<PairFilter>? _pairSearch;

        /// <summary>Steps whose pair search ran on the worker pool, and its blocks that filled their buffers (for tests).</summary>
        internal (long Runs, long Overflows) ParallelPairSearch => _pairSearch == null ? (0, 0) : (_pairSearch.Runs, _pairSearch.Overflows);

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
                Array.Resize(ref _refit, n);
                Array.Resize(ref _wantedBox, n);
            }
            _shapeMotion[shape] = 0;
            _shapePoseStep[shape] = -1;
            Aabb local = Shapes.Geometry[shape].ComputeAabb(Pose.Identity);
            _shapeRadius[shape] = local.Center.Length() + local.Extents.Length();
            _fatBoxStep[shape] = _stepIndex;
            int b = Shapes.Body[shape];
            bool isStatic = Bodies.Type[b] == BodyType.Static;
            Aabb fat = Shapes.WorldAabb[shape].Expanded(CollisionMargins.AabbMargin + SpeculativeBase);
            Shapes.ProxyId[shape] = _broadPhase.CreateProxy(fat, shape, isStatic);
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
            _broadPhase.DestroyProxy(Shapes.ProxyId[shape]);
            Shapes.ProxyId[shape] = -1;
            OnCcdShapeRemoved(Shapes.Body[shape]);
            ForgetIgnoredPairs(shape);
        }

        /// <summary>
        /// <see cref="StepStage.BroadPhase"/>: refreshes the bounds of awake moving shapes, swept
        /// over their predicted motion in this step, moves the proxies whose swept bounds left
        /// their fat boxes (or whose fat boxes became far too loose), then finds the new pairs,
        /// which the pair filter (<see cref="AcceptsPair"/> and <see cref="AddPair"/>, through
        /// <see cref="PairFilter"/>) turns into contacts; with threads, the tree queries and the
        /// filter's tests run on the worker pool first (<see cref="PairSearch{T}"/>). Reads: body poses,
        /// velocities and awake flags, shape geometry, layers and joints (through the filter).
        /// Writes: the shapes' world bounds, this step's shape poses and motion bounds, the
        /// proxies' fat boxes (and the step they changed), new contacts in the contact graph.
        /// </summary>
        void BroadPhase(float dt)
        {
            ShapeStorage s = Shapes;
            // Each moving shape's bounds, and whether its proxy needs a new fat box, are its own
            // (split between threads); the tree changes one proxy at a time, in shape order.
            BoundsJob job = _boundsJob ??= new BoundsJob(this);
            job.Dt = dt;
            IParallelScheduler? pool = ParallelScheduler();
            if (pool != null) pool.For(job, 0, s.ActiveCount, MinBoundsChunk);
            else job.Execute(0, s.ActiveCount);
            for (int k = 0; k < s.ActiveCount; k++)
            {
                if (!_refit[k]) continue;
                int i = s.Active[k];
                _broadPhase.MoveProxy(s.ProxyId[i], _wantedBox[k]);
                _fatBoxStep[i] = _stepIndex;
            }
            var filter = new PairFilter { World = this };
            if (pool != null) _pairSearch ??= new PairSearch<PairFilter>();
            _broadPhase.UpdatePairs(ref filter, _pairSearch, pool);
        }

        /// <summary>Shapes a thread takes at a time in the bounds pass.</summary>
        const int MinBoundsChunk = 256;

        /// <summary>
        /// The bounds pass over the active shapes [start, end): world pose, tight box, the box
        /// swept over the step's motion, and whether the proxy's fat box still holds it.
        /// </summary>
        sealed class BoundsJob : IParallelJob
        {
            readonly World _w;
            public float Dt;

            public BoundsJob(World world) => _w = world;

            public void Execute(int start, int end)
            {
                World w = _w;
                ShapeStorage s = w.Shapes;
                BodyStorage b = w.Bodies;
                float dt = Dt;
                float grow = w.SpeculativeBase;
                for (int k = start; k < end; k++)
                {
                    w._refit[k] = false;
                    int i = s.Active[k];
                    int body = s.Body[i];
                    if (b.Type[body] == BodyType.Static || !b.Awake[body]) continue;
                    Pose pose = w.ShapeWorldPose(i);
                    w._shapePose[i] = pose;
                    w._shapePoseStep[i] = w._stepIndex;
                    Aabb tight = s.Geometry[i].ComputeAabb(pose);
                    s.WorldAabb[i] = tight;
                    float angular = b.AngularVelocity[body].Length() * dt * CollisionMargins.Reach(tight, b.Center[body]);
                    Aabb swept = tight.Expanded(grow + angular);
                    Vector3 move = b.LinearVelocity[body] * dt;
                    w._shapeMotion[i] = move.Length() + angular;
                    swept = new Aabb(swept.Min + Vector3.Min(move, Vector3.Zero), swept.Max + Vector3.Max(move, Vector3.Zero));
                    w._refit[k] = w.NeedsRefit(s.ProxyId[i], swept, out w._wantedBox[k]);
                }
            }
        }

        // True when the proxy needs a new fat box (<paramref name="wanted"/>).
        bool NeedsRefit(int proxy, in Aabb swept, out Aabb wanted)
        {
            ref readonly Aabb fat = ref _broadPhase.FatAabb(proxy);
            wanted = swept.Expanded(CollisionMargins.AabbMargin);
            // A fat box four times the area it needs came from a fast phase that ended.
            return !(fat.Contains(swept) && fat.SurfaceArea <= 4f * wanted.SurfaceArea);
        }

        // The broad phase's pair callback: the world's pair filter.
        struct PairFilter : IPairCallback
        {
            public World World;
            public bool Accepts(int shapeA, int shapeB) => World.AcceptsPair(shapeA, shapeB);
            public void AddPair(int shapeA, int shapeB) => World.AddPair(shapeA, shapeB);
        }

        /// <summary>
        /// The pair filter's test, for each new overlap of fat boxes (reads only; the parallel
        /// pair search runs it on workers): true when the shapes are on different bodies, at
        /// least one of which is dynamic (or, for a sensor, not static), their layers accept
        /// each other, no joint between the bodies turns collision off, the pair is not
        /// ignored and a pair function exists.
        /// </summary>
        bool AcceptsPair(int shapeA, int shapeB)
        {
            ShapeStorage s = Shapes;
            int bodyA = s.Body[shapeA], bodyB = s.Body[shapeB];
            if (bodyA == bodyB) return false;
            bool sensor = s.IsSensor[shapeA] || s.IsSensor[shapeB];
            BodyType ta = Bodies.Type[bodyA], tb = Bodies.Type[bodyB];
            if (sensor ? ta == BodyType.Static && tb == BodyType.Static : ta != BodyType.Dynamic && tb != BodyType.Dynamic) return false;
            if ((s.CollidesWith[shapeA] & (1u << s.Layer[shapeB])) == 0 || (s.CollidesWith[shapeB] & (1u << s.Layer[shapeA])) == 0) return false;
            if (!sensor && JointBlocksCollision(bodyA, bodyB)) return false;
            if (IgnoresPair(shapeA, shapeB)) return false;
            return CollisionTable.Has(s.Geometry[shapeA].Type, s.Geometry[shapeB].Type);
        }

        /// <summary>
        /// Creates the contact of an accepted pair (<see cref="AcceptsPair"/>) unless the pair is
        /// known already. Shape A is the one with the lower type (the table's order), ties
        /// broken by slot.
        /// </summary>
        void AddPair(int shapeA, int shapeB)
        {
            if (ContactGraph.Find(shapeA, shapeB) >= 0) return;
            ShapeStorage s = Shapes;
            ShapeType ka = s.Geometry[shapeA].Type, kb = s.Geometry[shapeB].Type;
            if (kb < ka || (kb == ka && shapeB < shapeA)) (shapeA, shapeB) = (shapeB, shapeA);
            ContactGraph.Create(shapeA, shapeB, s.Body[shapeA], s.Body[shapeB], s.IsSensor[shapeA] || s.IsSensor[shapeB]);
        }
    }
}
