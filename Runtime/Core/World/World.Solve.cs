using System;
using Fulcrum.Collision;
using Fulcrum.Dynamics;

namespace Fulcrum
{
    public sealed partial class World
    {
        IslandBuilder _islands = new IslandBuilder();
        readonly SolverContext _solverContext = new SolverContext();
        readonly PgsSolver _pgs = new PgsSolver();
        readonly TgsSolver _tgs = new TgsSolver();
        int[] _freeBodies = Array.Empty<int>();
        WorkerPool? _workers;

        internal WorkerPool? SolverPoolForTests => _workers;

        internal SolverContext SolverContextForTests => _solverContext;

        // The solver's threads follow Settings.Threads; a change of count replaces the pool
        // (outside the steady state, so the allocation does not recur).
        WorkerPool? SolverThreads()
        {
            int threads = _settings.Threads;
            if (threads <= 1) return null;
            if (_workers == null || _workers.ThreadCount != threads)
            {
                _workers?.Stop();
                _workers = new WorkerPool(threads - 1);
            }
            return _workers;
        }

        /// <summary>The manifold pool that this step's contact set and the islands index into.</summary>
        ContactManifold[] StepManifolds() => Contacts.Pool;

        // Islands stage: wake what awake bodies touch, list the step's constraints, union-find.
        void BuildIslands()
        {
            _jointBreakCount = 0;
            Joints.EnsureBodies(Bodies.SlotCount);
            _islands.Build(Bodies, Shapes, Contacts.Pool, Contacts.Source, Contacts.ManifoldCount, Joints);
        }

        // Bodies in no constraint take the plain integrator step; the others go to the solver
        // the settings name (PGS or TGS).
        void Solve(float dt)
        {
            IConstraintSolver solver = _settings.Solver == SolverType.Pgs ? _pgs : (IConstraintSolver)_tgs;
            bool constrained = _islands.ManifoldCount > 0 || _islands.JointCount > 0;
            _stepConstrained = constrained;
            if (constrained)
            {
                _solverContext.Pool = SolverThreads();
                ContactManifold[] manifolds = StepManifolds();
                _solverContext.Begin(Bodies, Joints, manifolds, _islands, _settings, dt, solver.SubstepCount(_settings));
            }

            int free = 0;
            if (_freeBodies.Length < _islands.AwakeCount) _freeBodies = new int[Math.Max(16, 2 * _islands.AwakeCount)];
            for (int k = 0; k < _islands.AwakeCount; k++)
            {
                int i = _islands.AwakeBodies[k];
                if (!constrained || _solverContext.IndexOf(i) == 0) _freeBodies[free++] = i;
            }
            Integrator.IntegrateVelocities(Bodies, _freeBodies, 0, free, _settings.Gravity, dt, _settings.MaxLinearSpeed);
            Integrator.IntegratePositions(Bodies, _freeBodies, 0, free, dt);

            if (!constrained) return;
            if (SoftBodyStage != null && SoftBodyStage.HasWork)
            {
                // Only the soft-body stage asks (IntegratorSubsteps): a world without it skips this pass.
                if (_solvedInStep.Length < Bodies.SlotCount) Array.Resize(ref _solvedInStep, Math.Max(Bodies.SlotCount, 2 * _solvedInStep.Length));
                for (int k = 1; k < _solverContext.BodyCount; k++) _solvedInStep[_solverContext.BodySlot[k]] = _stepIndex + 1;
            }
            StatMaxJointError = MathF.Max(StatMaxJointError, solver.Step(_solverContext, _islands, dt));
            CollectBrokenJoints();
        }

        bool _stepConstrained;
        // Per body slot: 1 + the index of the last step whose constraint solver moved it.
        long[] _solvedInStep = Array.Empty<long>();

        /// <summary>
        /// How many integrator substeps moved body <paramref name="slot"/> in this step's solve:
        /// the TGS substeps for a body the solver took, 1 for PGS and for a body in no
        /// constraint (the plain integrator). Valid from the solve to the end of the step; the
        /// soft-body stage uses it to tell the rigid solve's constraint corrections from its
        /// integration.
        /// </summary>
        internal int IntegratorSubsteps(int slot) =>
            _stepConstrained && _settings.Solver == SolverType.Tgs && slot < _solvedInStep.Length && _solvedInStep[slot] == _stepIndex + 1 ? _settings.Substeps : 1;

        // Sleep half of the last stage: rest timers, then resting islands fall asleep.
        void UpdateSleep(float dt)
        {
            ContactManifold[] manifolds = StepManifolds();
            _islands.UpdateSleep(Bodies, manifolds, Joints, _settings, dt);
        }

        /// <summary>Wakes the sleeping island of body <paramref name="slot"/>, if it sleeps in one.</summary>
        void WakeIsland(int slot) => _islands.WakeIsland(Bodies, slot);

        // A removed body may have held others up: wake everything that touches it (sleeping
        // neighbours included, through the persistent contacts), and take its joints with it.
        // Runs before its shapes, and so its contacts, are released.
        void OnBodyDestroyed(int slot)
        {
            WakeIsland(slot);
            ContactGraph g = ContactGraph;
            for (int s = Bodies.FirstShape[slot]; s >= 0; s = Shapes.NextInBody[s])
            {
                for (int e = g.FirstEdge(s); e >= 0; e = g.NextEdge(e))
                {
                    ref Contact c = ref g.Contacts[e >> 1];
                    if ((c.Flags & ContactFlags.Touching) == 0) continue;
                    Wake(c.BodyA == slot ? c.BodyB : c.BodyA);
                }
            }
            DestroyJointsOf(slot);
        }
    }
}
