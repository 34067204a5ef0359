using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Solves the anchor rows (<see cref="PointConstraintPart"/>) of the step's joints exactly,
    /// all at once, where the joints form trees: Baraff's linear-time direct solve ("Linear-Time
    /// Dynamics using Lagrange Multipliers", SIGGRAPH 1996). A Gauss-Seidel row is a spring on
    /// its own effective mass, the light side's, so a 1000 kg load under 1 kg links stretched
    /// each joint 134 mm at the defaults; solved as one block the rows hold any mass ratio.
    /// <para>
    /// The system for the impulses lambda (on B; A gets the opposite) and the velocity changes dv
    /// is the symmetric, sparse one
    /// <code>
    ///   [  M  -J^T ] [ dv     ]   [ 0          ]
    ///   [ -J   0   ] [ lambda ] = [ J v + bias ]
    /// </code>
    /// with J v = vB + wB x rB - vA - wA x rA per joint (blocks [I, -[r]] with sign + for B, - for
    /// A). Bodies (6x6 blocks M = diag(m, m, m, I)) and joints (3x3 blocks) are the nodes of a
    /// graph that is a forest when the joints are: eliminated leaves first (block LDL^T in that
    /// order), no block fills in, so the factorisation and each solve cost O(nodes). Static and
    /// kinematic bodies are not nodes (infinite mass): a joint to one is a leaf of its body, and
    /// since a leaf joint's block would be zero, such a joint is made the root of its tree; a
    /// tree takes at most one of them.
    /// </para>
    /// <para>
    /// Which joints: the anchor rows of ball, hinge, fixed and cone-twist joints between bodies
    /// without axis locks, taken in solver order as long as they close no loop (through other
    /// joints, or through the ground by a second anchor to a static body), and with them the
    /// rotation rows of welds (three, J = [0, ±I]) and hinges (two, J = [0, ±u]) near their
    /// target; a rigid distance joint (min = max) joins as its one length row, J = ±[n, r x n],
    /// a rope (min &lt; max) pulled taut as its upper limit row (an equality that may only pull),
    /// both with compliant rows for their geometric stiffness, two across them and two for each
    /// end's turning under the pull (see Factor and Tilt),
    /// and a prismatic joint as its two rows across the slide axis and its rotation lock. A joint
    /// further apart than its capped bias closes at full rate keeps its rows
    /// (it is being pulled in). A hinge on or closing on an angle limit brings that row too (see
    /// RestingLimit), a slider on or closing on a slide limit that row (see RestingSlide), and a
    /// cone-twist joint whose tree carries a heavy load its cone and twist limits (see RestingCone
    /// and GateLimits). The rest (a loop's closing joint, a bridge's second anchor, a hinge's stop
    /// being left fast, motors, lightly laden cone-twist limits, friction, springs) stay in the Gauss-Seidel
    /// passes, and the block is one more item of those passes (block Gauss-Seidel): solved after
    /// the last biased sweep of a TGS substep and after its relax sweep (after every sweep it cost
    /// ragdolls 40 % more, every test passing either way), and after every PGS velocity sweep (only after
    /// the last, a hinge's joint friction stopped holding: the block undid what it held). The solve gives the rigid impulses x = -A^-1 (J v + bias); each row then
    /// takes the soft step's coefficients, dLambda = massScale x - impulseScale lambda, so a
    /// biased row is a spring of JointHertz on the tree's true effective mass (a chain sags
    /// g / omega^2 whatever it holds) and a violated joint is pulled in at the soft rate, capped
    /// at the correction speed. TGS and PGS (its velocity passes, which have no bias; its position
    /// passes stay row by row); <see cref="WorldSettings.JointTrees"/> turns it off.
    /// </para>
    /// Factorised at the start of the step and after each position update (the arms and the
    /// world inertias change there only); every pass in between reuses it. Double precision:
    /// the blocks mix 1 kg links with 1e6 kg loads. Arrays are kept between steps and grow only.
    /// </summary>
    internal sealed partial class JointTreeSolver
    {
        // Rows a joint node may hold (a rod's seven: length, two across, two tilt rows per end), the
        // stride of every node's block and vector slots; body nodes use six of them.
        const int Stride = 7;
        const int Block = Stride * Stride;

        // Offset of entry (row, column) in a node's block.
        static int At(int row, int column) => Stride * row + column;

        // Nodes. A body node holds its solver body index, a joint node its joint slot.
        int[] _body = new int[16];
        int[] _dim = new int[16];
        int[] _joint = new int[16];
        int[] _parent = new int[16];
        int[] _order = new int[16];
        int _nodes;
        // Per joint node: its body nodes on side A and B (-1: static or kinematic) and arms.
        int[] _nodeA = new int[16], _nodeB = new int[16];
        Vector3[] _armA = new Vector3[16], _armB = new Vector3[16], _gap = new Vector3[16];
        // Per joint node: its row set, named by kind (Ball: the anchor's 3 alone; Fixed: and 3
        // about the world axes; Hinge: and 2 about u1, u2; Distance: the length row, a taut
        // rope's upper limit, 2 compliant rows across it and 2 tilt rows per end; Prismatic: 2 across the slide
        // axis and the 3 of the lock), their axes, the error of the
        // rows after the anchor's (rotation vector, hinge errors, length error), and each row's
        // soft scales (6 per node).
        JointKind[] _rows = new JointKind[16];
        Vector3[] _axes = new Vector3[48];
        Vector3[] _error = new Vector3[16];
        Vector2[] _scale = new Vector2[16 * Stride];
        bool[] _leaf = new bool[16];
        // Per joint node: its one-sided row (a stop, a rope) released for this factorisation.
        bool[] _free = new bool[16];
        // Per distance node: which ends' turning its tilt rows hold (bit 0: A, rows 3-4; bit 1: B, rows 5-6; see Tilt).
        byte[] _tilt = new byte[16];
        // Per cone-twist node: its one-sided rows released for this factorisation (bit 0: the cone, row 3; bit 1: the twist limit, row 4).
        byte[] _released = new byte[16];
        // Per node: the mass of its subtree (GateLimits).
        float[] _subtreeMass = new float[16];
        // Factor: D^-1 (Stride x Stride per node), H_ip (the block to the parent, rows of i, Stride x Stride room) and L = D^-1 H_ip.
        double[] _dinv = new double[16 * Block], _h = new double[16 * Block], _l = new double[16 * Block];
        double[] _x = new double[16 * Stride];
        // Per body node, the impulses of one Apply summed: linear, then angular about the centre.
        double[] _sum = new double[16 * 6];
        readonly double[] _scratch = new double[Stride];
        // Build: union-find over solver bodies, per-body node and adjacency.
        int[] _find = new int[16], _bodyNode = new int[16], _first = new int[16], _next = new int[32], _stack = new int[16];
        bool[] _anchored = new bool[16];
        int[] _direct = new int[16];
        int _directCount;
        bool _stale;

        /// <summary>Joints whose anchor rows the block solves this step.</summary>
        public int DirectCount => _directCount;

        /// <summary>
        /// Picks this step's tree joints (see the class) and marks them
        /// (<see cref="JointData.DirectPoint"/>); clears every mark when <paramref name="enabled"/> is false.
        /// </summary>
        public void Build(SolverBody[] bodies, int bodyCount, JointData[] data, int[] jointOrder, int jointCount, in Softness soft, float dt, bool enabled)
        {
            _directCount = 0;
            _nodes = 0;
            for (int k = 0; k < jointCount; k++)
            {
                data[jointOrder[k]].DirectPoint = false;
                data[jointOrder[k]].DirectRotation = false;
                data[jointOrder[k]].DirectLimit = 0;
            }
            if (!enabled || jointCount == 0) return;
            Grow(ref _find, bodyCount);
            Grow(ref _bodyNode, bodyCount);
            if (_anchored.Length < bodyCount) _anchored = new bool[Math.Max(bodyCount, 2 * _anchored.Length)];
            Grow(ref _direct, jointCount);
            for (int i = 0; i < bodyCount; i++)
            {
                _find[i] = i;
                _anchored[i] = false;
                _bodyNode[i] = -1;
            }
            for (int k = 0; k < jointCount; k++)
            {
                int slot = jointOrder[k];
                ref JointData j = ref data[slot];
                // A distance joint joins as its one length row when the length is rigid (min =
                // max), and as its upper limit row when it is a rope pulled taut (see Taut).
                bool rod = j.Kind == JointKind.Distance, slider = j.Kind == JointKind.Prismatic;
                bool rope = rod && j.MinLength != j.MaxLength;
                if (rope && !Taut(j)) continue;
                int a = j.SolverA, b = j.SolverB;
                if (a < 0 || b < 0) continue;
                bool dynA = Treeable(bodies[a], a, out bool lockedA), dynB = Treeable(bodies[b], b, out bool lockedB);
                if (lockedA || lockedB || !(dynA || dynB)) continue;
                // A joint further apart than its capped bias closes at full rate (created off its
                // target) is pulled in by its own soft rows: as one block over the tree's true
                // effective mass it lifted a 1.6 t body toward targets other joints contradict
                // (WorldFuzz seed 69).
                Vector3 gap = j.DeltaCenter + j.ArmB - j.ArmA;
                float error = rope ? j.MaxLength - gap.Length() : rod ? gap.Length() - j.MinLength : gap.Length();
                if (slider)
                {
                    // Across the slide axis and the rotation lock; sliding along it is free.
                    SliderRows(j.FrameA, gap, out _, out _, out float c1, out float c2);
                    error = MathF.Max(MathF.Sqrt(c1 * c1 + c2 * c2), RotationLockPart.Error(j.FrameA, j.FrameB).Length());
                }
                if (soft.BiasRate * MathF.Abs(error) > soft.MaxBias) continue;
                if (dynA && dynB)
                {
                    int ra = Find(a), rb = Find(b);
                    if (ra == rb || (_anchored[ra] && _anchored[rb])) continue;
                    _find[ra] = rb;
                    _anchored[rb] |= _anchored[ra];
                }
                else
                {
                    int r = Find(dynA ? a : b);
                    if (_anchored[r]) continue;
                    _anchored[r] = true;
                }
                j.DirectPoint = true;
                // The rotation rows of a weld and of a hinge join the block when they are near
                // their target (a hinge within its small-angle rows' range, well conditioned).
                if (j.Kind == JointKind.Fixed)
                    j.DirectRotation = soft.BiasRate * RotationLockPart.Error(j.FrameA, j.FrameB).Length() <= soft.MaxBias;
                else if (j.Kind == JointKind.Hinge)
                {
                    HingeRows(j.FrameA, j.FrameB, out _, out _, out float e1, out float e2);
                    j.DirectRotation = soft.BiasRate * MathF.Sqrt(e1 * e1 + e2 * e2) <= soft.MaxBias;
                    if (j.DirectRotation) j.DirectLimit = RestingLimit(j, soft, bodies[a].AngularVelocity, bodies[b].AngularVelocity, dt);
                }
                else if (slider)
                    j.DirectLimit = RestingSlide(j, soft, bodies[a].PointVelocity(j.ArmA + gap), bodies[b].PointVelocity(j.ArmB), gap, dt);
                else if (j.Kind == JointKind.ConeTwist)
                    j.DirectLimit = (sbyte)(TreeLimits | RestingCone(j, soft, bodies[a].AngularVelocity, bodies[b].AngularVelocity, dt));
                _direct[_directCount++] = slot;
            }
            if (_directCount > 0) Arrange(bodies, data);
        }

        /// <summary>
        /// One exact update of every tree's anchor rows from the bodies' velocities now: the
        /// impulses are added to the rows' accumulated ones (warm start and reports read them)
        /// and the velocity changes to the bodies. With <paramref name="useBias"/> each row asks
        /// for the soft bias velocity of <paramref name="soft"/> toward its error.
        /// </summary>
        public void Solve(SolverBody[] bodies, JointData[] data, in Softness soft, float h, bool useBias)
        {
            if (_nodes == 0) return;
            if (_stale)
            {
                if (!Factor(bodies, data, h))
                {
                    // Not expected (a tree's system is nonsingular); the rows go back to Gauss-Seidel.
                    for (int k = 0; k < _directCount; k++)
                    {
                        data[_direct[k]].DirectPoint = data[_direct[k]].DirectRotation = false;
                        data[_direct[k]].DirectLimit = 0;
                    }
                    _directCount = 0;
                    _nodes = 0;
                    return;
                }
                _stale = false;
            }
            Compute(bodies, data, soft, h, useBias);
            // One-sided rows (a stop, a rope) the block would have pull: released (their row made
            // free) and the block solved once more, so the other rows do not lean on an impulse
            // the clamp below takes away (clamped alone, a limb lifting off its stop pushed its
            // joints apart).
            if (Release(bodies, data) && Factor(bodies, data, h)) Compute(bodies, data, soft, h, useBias);
            Apply(bodies, data);
        }

        /// <summary>Marks the factorisation stale: the bodies moved (arms, gaps and world inertias changed).</summary>
        public void Invalidate()
        {
            _stale = true;
            // Each position update starts with every one-sided row (a stop, a rope) held again.
            for (int i = 0; i < _nodes; i++)
            {
                _free[i] = false;
                _released[i] = 0;
            }
        }

        static void Grow(ref int[] a, int n)
        {
            if (a.Length < n) a = new int[Math.Max(n, 2 * a.Length)];
        }
    }
}
