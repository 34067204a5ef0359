using System;
using Fulcrum.SoftBodies;

namespace Fulcrum.Components
{
    public sealed partial class SoftBody
    {
        SoftSolver _solver = SoftSolver.Xpbd;
        int _substeps;
        int _iterations = 1;
        float _dampingTime = 0.01f;

        /// <summary>
        /// The elastic solver: XPBD (default; fast, soft materials) or Newton (implicit Euler,
        /// converges on stiff materials; tetrahedral meshes only: a cloth body keeps XPBD). See Documentation~/SoftSolvers.md.
        /// Takes effect at once on a live body.
        /// </summary>
        public SoftSolver solver
        {
            get => _solver;
            set
            {
                if (value != SoftSolver.Xpbd && value != SoftSolver.Newton) throw new ArgumentException($"{this}: solver {value} is not a solver.", nameof(solver));
                if (value == SoftSolver.Newton && _mesh != null && _mesh.IsShell)
                    throw new ArgumentException($"{this}: the Newton solver needs a tetrahedral mesh; '{_mesh}' is a shell (cloth).", nameof(solver));
                ThrowIfStepping(nameof(solver));
                _solver = value;
                SoftBodies.SoftBody? b = body;
                if (b != null) b.Solver = value;
            }
        }

        /// <summary>Substeps per world step, 0-1000; 0 picks them from the step (10 at 60 Hz for XPBD). Default: 0.</summary>
        public int substeps
        {
            get => _substeps;
            set
            {
                if (value < 0 || value > 1000) throw new ArgumentException($"{this}: substeps must be in [0, 1000], got {value}.", nameof(substeps));
                ThrowIfStepping(nameof(substeps));
                _substeps = value;
                SoftBodies.SoftBody? b = body;
                if (b != null) b.Substeps = value;
            }
        }

        /// <summary>Constraint iterations per substep, 1-1000. Default: 1.</summary>
        public int iterations
        {
            get => _iterations;
            set
            {
                if (value < 1 || value > 1000) throw new ArgumentException($"{this}: iterations must be in [1, 1000], got {value}.", nameof(iterations));
                ThrowIfStepping(nameof(iterations));
                _iterations = value;
                SoftBodies.SoftBody? b = body;
                if (b != null) b.Iterations = value;
            }
        }

        /// <summary>Stiffness-proportional damping time, seconds (&gt;= 0): how quickly wobbles die. Default: 0.01 s.</summary>
        public float dampingTime
        {
            get => _dampingTime;
            set
            {
                SetNonNegative(ref _dampingTime, value, nameof(dampingTime));
                SoftBodies.SoftBody? b = body;
                if (b != null) b.DampingTime = value;
            }
        }

        void ApplySettings(ref SoftBodyDef def)
        {
            def.Solver = _mesh != null && _mesh.IsShell ? SoftSolver.Xpbd : _solver;
            def.Substeps = _substeps;
            def.Iterations = _iterations;
            def.DampingTime = _dampingTime;
        }
    }
}
