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
                SetCount(ref _substeps, value, 0, nameof(substeps));
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
                SetCount(ref _iterations, value, 1, nameof(iterations));
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

        // The head of the substeps and iterations setters: a count in [min, 1000], refused
        // mid-step, then stored; the caller then hands it to the live body.
        void SetCount(ref int field, int value, int min, string member)
        {
            if (value < min || value > 1000) throw new ArgumentException($"{this}: {member} must be in [{min}, 1000], got {value}.", member);
            ThrowIfStepping(member);
            field = value;
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
