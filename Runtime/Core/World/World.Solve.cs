using System;
using Fulcrum.Collision;
using Fulcrum.Dynamics;

namespace Fulcrum
{
    public sealed partial class World
    {
        readonly SolverContext _solverContext = new SolverContext();
        readonly PgsSolver _pgs = new PgsSolver();
        readonly TgsSolver _tgs = new TgsSolver();
        int[] _freeBodies = Array.Empty<int>();
        internal SolverContext SolverContextForTests => _solverContext;

        /// <summary>The manifold pool that this step's contact set and the islands index into.</summary>
        ContactManifold[] StepManifolds() => Contacts.Pool;

        /// <summary>
        /// <see cref="StepStage.Solve"/>: bodies in no constraint take the plain integrator step;
        /// the others go to the solver the settings name (PGS or TGS), which integrates
        /// velocities, solves contacts and joints and integrates positions.
        /// Reads: the islands' awake bodies, manifolds and joints; body velocities, forces and
        /// poses; the settings. Writes: body poses and velocities, the manifolds' accumulated
        /// impulses, the joints' impulses and reports (force, torque, stress, error), the
        /// solved-in-step stamps (only with a soft-body stage) and <see cref="StatMaxJointError"/>.
        /// Joints over their breaking threshold are only marked by their stress here; they break
        /// in <see cref="SleepAndEvents"/>.
        /// </summary>
        void Solve(float dt)
        {
            IConstraintSolver solver = _settings.Solver == SolverType.Pgs ? _pgs : (IConstraintSolver)_tgs;
            bool constrained = _islands.ManifoldCount > 0 || _islands.JointCount > 0;
            _stepConstrained = constrained;
            if (constrained)
            {
                _solverContext.Pool = ParallelScheduler();
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
    }
}
