using System;
using System.Numerics;

namespace Fulcrum
{
    /// <summary>
    /// World-wide simulation settings. Start from <see cref="Default"/>; every field documents
    /// its default and unit. Checked by <see cref="Validate"/> whenever a world takes them.
    /// </summary>
    public struct WorldSettings
    {
        /// <summary>Gravity, m/s^2. Default: (0, -9.81, 0).</summary>
        public Vector3 Gravity;
        /// <summary>The constraint solver. Default: <see cref="SolverType.Tgs"/>.</summary>
        public SolverType Solver;
        /// <summary>
        /// Velocity iterations: per step for PGS, per substep for TGS. &gt;= 1. Default: 4.
        /// Under PGS a tall column needs many: a 20-box tower stacked +-1 mm off falls at 4-10
        /// iterations, creeps at 16-20 and stays put at 30. TGS's substeps multiply its
        /// iterations: the default holds a 40-box tower while sleeping is on (it sleeps within
        /// 2 s); with sleeping off the column buckles after about 15 s (see ContactHertz).
        /// </summary>
        public int Iterations;
        /// <summary>Substeps per step (TGS; PGS ignores it). &gt;= 1. Default: 4.</summary>
        public int Substeps;
        /// <summary>
        /// Position iterations of PGS: non-linear Gauss-Seidel passes that move bodies to remove
        /// overlap beyond <see cref="LinearSlop"/> and joint error (a fraction 0.2 per pass, at most
        /// <see cref="MaxContactPushSpeed"/> x dt), without touching velocities. TGS ignores it. &gt;= 0. Default: 2.
        /// </summary>
        public int PositionIterations;
        /// <summary>
        /// Relax passes per TGS substep: unbiased passes after the position update that take out
        /// the velocity the soft bias added (so pushing out adds no energy). PGS ignores it. &gt;= 0. Default: 1.
        /// </summary>
        public int RelaxIterations;
        /// <summary>Reuse last step's impulses as the starting guess. Default: true.</summary>
        public bool WarmStarting;
        /// <summary>
        /// Solve the normal rows of a 2-4 point manifold together (block solver: pairs of points
        /// by exact 2x2 LCP enumeration). Keeps the support of a face contact symmetric, which
        /// tall stacks need. Default: true.
        /// </summary>
        public bool BlockSolver;
        /// <summary>Let resting islands fall asleep. Default: true.</summary>
        public bool EnableSleeping;
        /// <summary>Seconds a body must stay below the sleep thresholds before its island sleeps. Default: 0.5 s.</summary>
        public float TimeToSleep;
        /// <summary>Linear speed below which a body counts as resting, m/s. Default: 0.05 m/s.</summary>
        public float SleepLinearVelocity;
        /// <summary>Angular speed below which a body counts as resting, rad/s. Default: 0.05 rad/s.</summary>
        public float SleepAngularVelocity;
        /// <summary>Worker threads for the parallel stages; 1 runs everything on the caller's thread. Default: 1.</summary>
        public int Threads;
        /// <summary>Bit-identical results for any thread count (fixed orders, no racy sums). Default: true.</summary>
        public bool Deterministic;
        /// <summary>
        /// Contact stiffness of the soft contact constraint (TGS), Hz; clamped to a quarter of the
        /// substep rate (the stiffest the soft step keeps stable: half the substep rate already
        /// shakes a 40-box tower), and doubled against static and kinematic bodies (within the
        /// same clamp). The default is above the clamp, so contacts are as stiff as the substeps
        /// allow: 60 Hz at 60 Hz x 4 substeps, 120 Hz at 8, 240 Hz at 16. Soft contacts sag under
        /// load by about (load / effective mass) g / (2 pi f)^2, and a tall column on soft
        /// contacts buckles once its weight's moment beats the contacts' tilt stiffness (which
        /// grows as f^2): at 60 Hz a 40-box tower stands until it sleeps (sag 0.11 m; kept awake
        /// it topples after about 15 s, between 120 and 240 Hz it stays), a 100-box tower stacked
        /// +-1 mm off needs 16 substeps to stand 10 s (sag 43 mm) and 32 to stay put.
        /// Default: 1000 Hz.
        /// </summary>
        public float ContactHertz;
        /// <summary>Damping ratio of the soft contact constraint (1 = critical). Default: 10.</summary>
        public float ContactDampingRatio;
        /// <summary>
        /// Shock propagation: after the biased passes of each TGS substep (after PGS's velocity
        /// passes), one sweep from the ground up removes each body's approach to the body it rests
        /// on, that body held still, wherever it would carry their contact past
        /// <see cref="ShockDepth"/> (ShockPropagation; Documentation~/MassRatio.md). It carries the
        /// ground's support up a stack whatever the mass ratio and whatever the shapes; it only
        /// removes approach, so it never adds energy.
        /// Default: true.
        /// </summary>
        public bool ShockPropagation;
        /// <summary>
        /// The depth, m, past which <see cref="ShockPropagation"/> stops a contact sinking: shallower
        /// contacts rest on the soft solver alone (a box on a box rests 0.14 mm deep at 60 Hz), so
        /// the sweep changes nothing in ordinary stacks and holds heavy loads here (at 1 mm a 40-row
        /// pyramid's top drifts 21 mm instead of 12 mm as the sweep starts acting inside it). Default: 2 mm.
        /// </summary>
        public float ShockDepth;
        /// <summary>
        /// Joint trees (TGS, and PGS's velocity passes): the anchor rows of ball, hinge, fixed and
        /// cone-twist joints that form trees (with the rotation rows of welds and hinges, rigid
        /// distance joints' length rows, prismatic joints' cross rows and lock, and the limits a
        /// hinge, a slider or a heavy-laden cone-twist joint rests on) are
        /// solved exactly, as one block per
        /// iteration (Baraff's linear-time solve; JointTreeSolver), so a heavy load on light links
        /// does not stretch them: a Gauss-Seidel row is a spring on the light side's effective
        /// mass. Loops, locked bodies and the other rows stay iterative. Default: true.
        /// </summary>
        public bool JointTrees;
        /// <summary>
        /// Stiffness of joint rows (TGS), Hz; clamped to a quarter of the substep rate, where the
        /// soft step stays stable. Default: 60 Hz.
        /// </summary>
        public float JointHertz;
        /// <summary>Damping ratio of joint rows (TGS). Default: 5.</summary>
        public float JointDampingRatio;
        /// <summary>
        /// The fastest a joint's soft rows (TGS) pull a violated joint back together: m/s for
        /// anchors and slides, rad/s for angles and limits. A joint created far from its target
        /// (bodies overlapping, axes misaligned, a hinge outside its limits) converges at this
        /// speed instead of being kicked at the bias rate times its error (a hinge 160 degrees
        /// outside its limits was spun at 90 rad/s in the first step and blew up). Default: 4.
        /// </summary>
        public float MaxJointCorrectionSpeed;
        /// <summary>The fastest the solver may push overlapping bodies apart, m/s. Default: 3 m/s.</summary>
        public float MaxContactPushSpeed;
        /// <summary>Penetration allowed without correction, m. Default: 0.005 m.</summary>
        public float LinearSlop;
        /// <summary>Relative normal speed below which restitution is ignored, m/s. Default: 1 m/s.</summary>
        public float RestitutionThreshold;
        /// <summary>
        /// Speed cap for any point of a dynamic body, m/s (keeps a blown-up scene finite): each
        /// velocity update, and the solver's result before it moves the bodies, clamps the
        /// centre's speed to it, and the angular speed to
        /// MaxLinearSpeed / r (r: the farthest point of the body's shapes from its centre of
        /// mass) and to <see cref="Limits.MaxAngularSpeed"/>, so spin cannot fling a point past
        /// it either. A larger input velocity (up to <see cref="Limits.MaxInputSpeed"/>) is
        /// clamped at the next step, never zeroed. At most Limits.MaxInputSpeed. Default: 400 m/s.
        /// </summary>
        public float MaxLinearSpeed;
        /// <summary>
        /// Manifold reuse: a touching pair whose relative pose moved less than this distance (m)
        /// and <see cref="ManifoldReuseAngle"/> since its manifold was computed keeps that
        /// manifold, its points carried rigidly with the two shapes, instead of running the pair
        /// function again (the body-pair cache of Jolt). Resting stacks and piles then skip
        /// nearly all of their narrow phase. 0 turns reuse off. Default: 0.001 m.
        /// </summary>
        public float ManifoldReuseDistance;
        /// <summary>The relative rotation, radians, below which a manifold may be reused (see
        /// <see cref="ManifoldReuseDistance"/>). 0 turns reuse off. Default: 2 degrees.</summary>
        public float ManifoldReuseAngle;

        /// <summary>The defaults documented on each field.</summary>
        public static WorldSettings Default => new WorldSettings
        {
            Gravity = new Vector3(0, -9.81f, 0),
            Solver = SolverType.Tgs,
            Iterations = 4,
            Substeps = 4,
            PositionIterations = 2,
            RelaxIterations = 1,
            WarmStarting = true,
            BlockSolver = true,
            EnableSleeping = true,
            TimeToSleep = 0.5f,
            SleepLinearVelocity = 0.05f,
            SleepAngularVelocity = 0.05f,
            Threads = 1,
            Deterministic = true,
            ContactHertz = 1000f,
            ContactDampingRatio = 10f,
            ShockPropagation = true,
            ShockDepth = 0.002f,
            JointTrees = true,
            JointHertz = 60f,
            JointDampingRatio = 5f,
            MaxJointCorrectionSpeed = 4f,
            MaxContactPushSpeed = 3f,
            LinearSlop = 0.005f,
            RestitutionThreshold = 1f,
            MaxLinearSpeed = 400f,
            ManifoldReuseDistance = 0.001f,
            ManifoldReuseAngle = 2f * MathF.PI / 180f,
        };

        /// <summary>Throws an <see cref="ArgumentException"/> naming the first bad field.</summary>
        public readonly void Validate()
        {
            Mathematics.Validate.Finite(Gravity, "settings.Gravity");
            if (Limits.Length(Gravity) > Limits.MaxGravity)
                throw new ArgumentException($"settings.Gravity must have magnitude at most {Limits.MaxGravity:G} m/s^2 (Limits.MaxGravity), got {Gravity}.", nameof(Gravity));
            if (Solver != SolverType.Pgs && Solver != SolverType.Tgs)
                throw new ArgumentException($"settings.Solver must be Pgs or Tgs, got {Solver}.", nameof(Solver));
            CheckCount(Iterations, 1, Limits.MaxIterations, nameof(Limits.MaxIterations), nameof(Iterations));
            CheckCount(Substeps, 1, Limits.MaxSubsteps, nameof(Limits.MaxSubsteps), nameof(Substeps));
            CheckCount(PositionIterations, 0, Limits.MaxIterations, nameof(Limits.MaxIterations), nameof(PositionIterations));
            CheckCount(RelaxIterations, 0, Limits.MaxIterations, nameof(Limits.MaxIterations), nameof(RelaxIterations));
            CheckCount(Threads, 1, Limits.MaxThreads, nameof(Limits.MaxThreads), nameof(Threads));
            Mathematics.Validate.Positive(TimeToSleep, "settings.TimeToSleep");
            Mathematics.Validate.NonNegative(SleepLinearVelocity, "settings.SleepLinearVelocity");
            Mathematics.Validate.NonNegative(SleepAngularVelocity, "settings.SleepAngularVelocity");
            Mathematics.Validate.Positive(ContactHertz, "settings.ContactHertz");
            Mathematics.Validate.NonNegative(ContactDampingRatio, "settings.ContactDampingRatio");
            Mathematics.Validate.NonNegative(ShockDepth, "settings.ShockDepth");
            Mathematics.Validate.Positive(JointHertz, "settings.JointHertz");
            Mathematics.Validate.NonNegative(JointDampingRatio, "settings.JointDampingRatio");
            Mathematics.Validate.Positive(MaxJointCorrectionSpeed, "settings.MaxJointCorrectionSpeed");
            Mathematics.Validate.Positive(MaxContactPushSpeed, "settings.MaxContactPushSpeed");
            Mathematics.Validate.NonNegative(LinearSlop, "settings.LinearSlop");
            Mathematics.Validate.NonNegative(RestitutionThreshold, "settings.RestitutionThreshold");
            Mathematics.Validate.Positive(MaxLinearSpeed, "settings.MaxLinearSpeed");
            if (MaxLinearSpeed > Limits.MaxInputSpeed)
                throw new ArgumentException($"settings.MaxLinearSpeed must be at most {Limits.MaxInputSpeed:G} m/s (Limits.MaxInputSpeed), got {MaxLinearSpeed}.", nameof(MaxLinearSpeed));
            Mathematics.Validate.NonNegative(ManifoldReuseDistance, "settings.ManifoldReuseDistance");
            Mathematics.Validate.NonNegative(ManifoldReuseAngle, "settings.ManifoldReuseAngle");
            if (ManifoldReuseAngle > MathF.PI)
                throw new ArgumentException($"settings.ManifoldReuseAngle must be at most pi, got {ManifoldReuseAngle}.", nameof(ManifoldReuseAngle));
        }

        // Iterations, substeps, threads: a count in [min, max], max being the Limits constant named <limit>.
        static void CheckCount(int value, int min, int max, string limit, string field)
        {
            if (value < min || value > max)
                throw new ArgumentException($"settings.{field} must be in {min}..{max} (Limits.{limit}), got {value}.", field);
        }
    }
}
