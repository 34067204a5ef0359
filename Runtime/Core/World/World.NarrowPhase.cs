using Fulcrum.Collision;

namespace Fulcrum
{
    public sealed partial class World
    {
        // The narrow phase owns the contacts, their manifolds and this step's list for the solver.
        readonly NarrowPhase _narrowPhase = new NarrowPhase();

        /// <summary>The persistent contacts and their manifolds (the narrow phase's).</summary>
        internal ContactGraph ContactGraph => _narrowPhase.Graph;

        /// <summary>This step's manifolds for the solver (see <see cref="ContactSet"/>).</summary>
        internal ContactSet Contacts => _narrowPhase.Contacts;

        /// <summary>Steps whose narrow phase ran its pair functions on the worker pool (for tests).</summary>
        internal long ParallelNarrowPhaseSteps => _narrowPhase.ParallelSteps;

        /// <summary>Contacts whose manifolds the worker pool rewrote in place (for tests).</summary>
        internal long ParallelManifoldRewrites => _narrowPhase.ParallelRewrites;

        /// <summary>
        /// <see cref="StepStage.NarrowPhase"/>: runs <see cref="Collision.NarrowPhase.Run{THost}"/>
        /// (Collision/NarrowPhase.cs): the pair functions of every contact with an awake body,
        /// impulses carried over by feature id or manifolds reused, and the manifolds listed for
        /// the solver in shape-pair order (<see cref="Contacts"/>). Reads: shape geometry, this
        /// step's shape poses, bounds and motion bounds, fat boxes, body velocities and awake
        /// flags. Writes: the contact graph (manifolds, flags, destroyed contacts),
        /// <see cref="Contacts"/>, <see cref="StatContactCount"/>, <see cref="StatMaxPenetration"/>
        /// and <see cref="StatReusedManifoldPairs"/>; wakes the sleeping bodies a new manifold
        /// touches and records the End events of touching contacts whose fat boxes parted
        /// (NarrowPhase.Run says why those two happen here).
        /// </summary>
        void NarrowPhase(float dt)
        {
            var input = new NarrowPhaseInput
            {
                Bodies = Bodies,
                Shapes = Shapes,
                BroadPhase = _broadPhase,
                ShapeMotion = _shapeMotion,
                ShapeRadius = _shapeRadius,
                ShapePose = _shapePose,
                ShapePoseStep = _shapePoseStep,
                FatBoxStep = _fatBoxStep,
                StepIndex = _stepIndex,
                Dt = dt,
                SpeculativeBase = SpeculativeBase,
                LinearSlop = _settings.LinearSlop,
                ReuseDistance = _settings.ManifoldReuseDistance,
                ReuseAngle = _settings.ManifoldReuseAngle,
                Threads = _settings.Threads,
            };
            var host = new NarrowPhaseHost { World = this };
            _narrowPhase.Run(input, ref host);
            StatContactCount = _narrowPhase.Touching;
            if (_narrowPhase.MaxPenetration > StatMaxPenetration) StatMaxPenetration = _narrowPhase.MaxPenetration;
            StatReusedManifoldPairs = _narrowPhase.ReusedPairs;
        }

        // What the narrow phase asks of the world: waking, End events, the worker threads.
        struct NarrowPhaseHost : INarrowPhaseHost
        {
            public World World;
            public void Wake(int body) => World.Wake(body);
            public void ContactEnded(int contact) => World.RecordStepEnd(contact);
            public IParallelScheduler? Workers() => World.ParallelScheduler();
        }
    }
}
