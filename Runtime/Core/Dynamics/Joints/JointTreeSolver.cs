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
    internal sealed class JointTreeSolver
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
        /// The angle limit a hinge rests on or closes on (+1 lower, -1 upper, 0 neither): within
        /// <see cref="LimitReach"/> of it, or closing fast enough to reach it within the step,
        /// not leaving it faster than <see cref="RestingSpin"/>, and not past it by more than the
        /// capped bias closes. Its row joins the block: speculative while the stop is ahead (the
        /// hinge may close the gap within the substep), an equality on it, and only ever pushing
        /// (a row the block would have pull is released and the block solved again, see Solve).
        /// Row by row the limit row was a spring on the light arm: a 1000 kg load on a 1 kg arm
        /// drooped 97 degrees past its stop, and swung onto it went 99 degrees through.
        /// </summary>
        static sbyte RestingLimit(in JointData j, in Softness soft, Vector3 wA, Vector3 wB, float dt)
        {
            if (!j.HasLowerLimit && !j.HasUpperLimit) return 0;
            float spin = Vector3.Dot(wB - wA, Vector3.Transform(Vector3.UnitX, j.FrameA));
            float angle = JointSolver.TwistAngle(j.FrameA, j.FrameB);
            if (j.HasLowerLimit && spin <= RestingSpin && angle - j.Lower <= LimitReach + MathF.Max(0, -spin) * dt
                && soft.BiasRate * (j.Lower - angle) <= soft.MaxBias) return 1;
            if (j.HasUpperLimit && spin >= -RestingSpin && j.Upper - angle <= LimitReach + MathF.Max(0, spin) * dt
                && soft.BiasRate * (angle - j.Upper) <= soft.MaxBias) return -1;
            return 0;
        }

        /// <summary>The fastest a hinge may turn away from a limit and still count as on it, rad/s: 0.2.</summary>
        const float RestingSpin = 0.2f;

        /// <summary>How close to an angle limit a hinge counts as resting on it, rad: 0.005 (0.3 degrees).</summary>
        const float LimitReach = 0.005f;

        /// <summary>
        /// The slide limit a prismatic joint rests on or closes on (+1 lower, -1 upper, 0 neither),
        /// as <see cref="RestingLimit"/> for a hinge: within <see cref="SlideReach"/> of it or closing
        /// fast enough to reach it within the step, and not past it by more than the capped bias
        /// closes. Its row joins the block as the hinge's stop does, scaled as the rows across the
        /// axis are (rigid among them, a 1000 kg load that struck the limit was thrown back 0.2 m).
        /// Also while it is being left: the block releases a row that would pull, where row by row
        /// the accumulated impulse that held the load, warm-started on the light carriage, threw a
        /// 1000 kg load thrown up at 1 m/s to 159 mm instead of 51. Row by row the limit row was a
        /// spring on the light carriage: a 1000 kg load welded under a 1 kg carriage on a vertical
        /// rail sat 69 mm past its lower limit, and 1e5 kg fell through it.
        /// </summary>
        static sbyte RestingSlide(in JointData j, in Softness soft, Vector3 vA, Vector3 vB, Vector3 gap, float dt)
        {
            if (!j.HasLowerLimit && !j.HasUpperLimit) return 0;
            Vector3 axis = Vector3.Transform(Vector3.UnitX, j.FrameA);
            float speed = Vector3.Dot(axis, vB - vA), at = Vector3.Dot(axis, gap);
            if (j.HasLowerLimit && at - j.Lower <= SlideReach + MathF.Max(0, -speed) * dt
                && soft.BiasRate * (j.Lower - at) <= soft.MaxBias) return 1;
            if (j.HasUpperLimit && j.Upper - at <= SlideReach + MathF.Max(0, speed) * dt
                && soft.BiasRate * (at - j.Upper) <= soft.MaxBias) return -1;
            return 0;
        }

        /// <summary>How close to a slide limit a prismatic joint counts as resting on it, m: 0.005.</summary>
        const float SlideReach = 0.005f;

        /// <summary>
        /// Which limits of a cone-twist joint the block takes this step (bits: <see cref="ConeRow"/>,
        /// <see cref="TwistLowerRow"/>, <see cref="TwistUpperRow"/>): each one the joint rests on or
        /// closes on, as a slider's limit (<see cref="RestingSlide"/>): within <see cref="LimitReach"/>
        /// of it or closing fast enough to reach it within the step, and not past it by more than
        /// the capped bias closes; also while it is being left (the block releases a row that
        /// would pull; a spin test as the hinge's let a 1 kg arm's momentary spin under 1e5 kg,
        /// cone and twist both held, drop the twist row, and the arm tore loose). Their rows (about
        /// the swing axis and the mean twist axis, as ConeTwistJointSolver's) join the block, scaled
        /// as the anchor rows, speculative while ahead, pushing only. Row by row each was a spring on
        /// the light arm: a 1000 kg load on a 1 kg arm resting on a 30 degree cone swung through it
        /// to 170 degrees, a twist limit of 10 degrees let it turn to 144, and under 1e5 kg the
        /// anchor gave way (the load fell 73 m).
        /// </summary>
        static sbyte RestingCone(in JointData j, in Softness soft, Vector3 wA, Vector3 wB, float dt)
        {
            int rows = 0;
            if (j.ConeAngle < MathF.PI)
            {
                ConeSwing(j.FrameA, j.FrameB, out Vector3 axis, out float swing);
                float rate = Vector3.Dot(axis, wB - wA);
                if (j.ConeAngle - swing <= LimitReach + MathF.Max(0, rate) * dt
                    && soft.BiasRate * (swing - j.ConeAngle) <= soft.MaxBias) rows |= ConeRow;
            }
            // The twist limits about the mean twist axis, as the hinge's stops about its axis; not
            // near a half-turn swing, where that axis (the frames' x axes summed) vanishes and
            // turns over: a 1e5 kg pendulum on a 1 kg link swinging through it tore loose.
            Vector3 sum = Vector3.Transform(Vector3.UnitX, j.FrameA) + Vector3.Transform(Vector3.UnitX, j.FrameB);
            if (j.TwistAngle < MathF.PI && sum.LengthSquared() > TwistAxisFloor)
            {
                Vector3 t = TwistAxis(j.FrameA, j.FrameB);
                float spin = Vector3.Dot(t, wB - wA), twist = JointSolver.TwistAngle(j.FrameA, j.FrameB);
                if (twist + j.TwistAngle <= LimitReach + MathF.Max(0, -spin) * dt
                    && soft.BiasRate * (-j.TwistAngle - twist) <= soft.MaxBias) rows |= TwistLowerRow;
                else if (j.TwistAngle - twist <= LimitReach + MathF.Max(0, spin) * dt
                    && soft.BiasRate * (twist - j.TwistAngle) <= soft.MaxBias) rows |= TwistUpperRow;
            }
            return (sbyte)rows;
        }

        /// <summary>
        /// The least squared length of the frames' x axes summed (4 cos^2(swing / 2)) at which a
        /// twist limit joins the block: 1, a swing of 120 degrees.
        /// </summary>
        const float TwistAxisFloor = 1f;

        /// <summary>
        /// Bits of a cone-twist joint's <see cref="JointData.DirectLimit"/>: the block holds its cone,
        /// its lower or its upper twist limit this step; TreeLimits: the block takes its limits as
        /// it meets them (the joint leaves a limit still ahead to the block, as a tree hinge its stop).
        /// </summary>
        const int ConeRow = 1, TwistLowerRow = 2, TwistUpperRow = 4, TreeLimits = 8;

        /// <summary>A cone-twist joint's twist axis (as ConeTwistJointSolver's): the mean of the frames' x axes.</summary>
        static Vector3 TwistAxis(Quaternion fA, Quaternion fB)
        {
            Vector3 ta = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 t = ta + Vector3.Transform(Vector3.UnitX, fB);
            float length = t.Length();
            return length > 1e-6f ? t / length : ta;
        }

        /// <summary>
        /// A cone-twist joint's swing (as ConeTwistJointSolver measures it): the angle between the
        /// frames' x axes, and the unit axis about which it grows (A's y axis when they are aligned).
        /// </summary>
        static void ConeSwing(Quaternion fA, Quaternion fB, out Vector3 axis, out float swing)
        {
            Vector3 ta = Vector3.Transform(Vector3.UnitX, fA), tb = Vector3.Transform(Vector3.UnitX, fB);
            Vector3 s = Vector3.Cross(ta, tb);
            float sin = s.Length();
            swing = MathF.Atan2(sin, Vector3.Dot(ta, tb));
            axis = sin > 1e-6f ? s / sin : Vector3.Transform(Vector3.UnitY, fA);
        }

        /// <summary>
        /// A rope (a distance joint with min &lt; max) joins the block while it is pulled taut: its
        /// length within 1 % of its maximum (or beyond it), with an upper limit. The block holds it
        /// as an equality at the maximum whose accumulated impulse may only pull (clamped at zero;
        /// a rope that goes slack in the step pushes nothing, and the next step leaves it out).
        /// Row by row, a 1000 kg load on five 1 kg links joined by 0.1 m ropes stretched them
        /// 0.73 m and 1e5 kg fell 108 m: the limit row is a spring on the light link's mass,
        /// as the anchor rows were.
        /// </summary>
        static bool Taut(in JointData j)
        {
            if (!j.HasUpperLimit) return false;
            float length = (j.DeltaCenter + j.ArmB - j.ArmA).Length();
            return length >= 0.99f * j.MaxLength;
        }

        // A dynamic body with a mass and an invertible inertia; kinematic and static ones are
        // not nodes (false); a locked dynamic body, or one whose inertia cannot be inverted,
        // takes its joints out of the block (locked).
        static bool Treeable(in SolverBody body, int index, out bool locked)
        {
            locked = false;
            if (index == 0 || body.IsDynamic == 0) return false;
            if (body.IsDynamic != 1 || !(body.InverseMass > 0)) { locked = true; return false; }
            Mat3 ii = body.InverseInertia;
            float det = Vector3.Dot(ii.C0, Vector3.Cross(ii.C1, ii.C2));
            if (!(det > 0) || !float.IsFinite(det)) { locked = true; return false; }
            return true;
        }

        int Find(int i)
        {
            while (_find[i] != i)
            {
                _find[i] = _find[_find[i]];
                i = _find[i];
            }
            return i;
        }

        // Nodes, adjacency, a root per tree and the elimination order (reverse pre-order: every
        // node after all of its descendants).
        void Arrange(SolverBody[] bodies, JointData[] data)
        {
            int capacity = 3 * _directCount + 1;
            Grow(ref _body, capacity);
            Grow(ref _joint, capacity);
            Grow(ref _parent, capacity);
            Grow(ref _order, capacity);
            Grow(ref _nodeA, capacity);
            Grow(ref _nodeB, capacity);
            Grow(ref _stack, capacity);
            Grow(ref _first, capacity);
            Grow(ref _dim, capacity);
            Grow(ref _next, 2 * capacity);
            if (_armA.Length < capacity)
            {
                _armA = new Vector3[capacity];
                _armB = new Vector3[capacity];
                _gap = new Vector3[capacity];
                _scale = new Vector2[Stride * capacity];
                _rows = new JointKind[capacity];
                _axes = new Vector3[3 * capacity];
                _error = new Vector3[capacity];
                _leaf = new bool[capacity];
                _free = new bool[capacity];
                _tilt = new byte[capacity];
                _released = new byte[capacity];
                _subtreeMass = new float[capacity];
            }
            if (_dinv.Length < Block * capacity)
            {
                _dinv = new double[Block * capacity];
                _h = new double[Block * capacity];
                _l = new double[Block * capacity];
                _x = new double[Stride * capacity];
            }
            int n = 0;
            for (int k = 0; k < _directCount; k++)
            {
                ref JointData j = ref data[_direct[k]];
                int jn = n++;
                _body[jn] = -1;
                _joint[jn] = _direct[k];
                bool cone = j.Kind == JointKind.ConeTwist && (j.DirectLimit & (ConeRow | TwistLowerRow | TwistUpperRow)) != 0;
                _rows[jn] = j.Kind == JointKind.Distance || j.Kind == JointKind.Prismatic || j.DirectRotation || cone ? j.Kind : JointKind.Ball;
                _dim[jn] = j.Kind == JointKind.Distance ? 3 : j.Kind == JointKind.Prismatic ? (j.DirectLimit != 0 ? 6 : 5)
                    : j.DirectRotation ? (j.Kind == JointKind.Fixed || j.DirectLimit != 0 ? 6 : 5) : cone ? 5 : 3;
                _nodeA[jn] = BodyNode(bodies, j.SolverA, ref n);
                _nodeB[jn] = BodyNode(bodies, j.SolverB, ref n);
            }
            _nodes = n;
            for (int i = 0; i < n; i++)
            {
                _free[i] = false;
                _released[i] = 0;
            }
            // Adjacency of body nodes: a linked list of (joint node) edges per body node.
            for (int i = 0; i < n; i++) _parent[i] = -2;
            for (int i = 0; i < n; i++) _first[i] = -1;
            for (int i = 0; i < n; i++)
            {
                if (_joint[i] < 0) continue;
                Link(_nodeA[i], i, 0);
                Link(_nodeB[i], i, 1);
            }
            int visited = 0;
            // Anchored joints first, as roots; then the bodies of trees without one.
            for (int pass = 0; pass < 2; pass++)
                for (int i = 0; i < n; i++)
                {
                    if (_parent[i] != -2) continue;
                    bool anchoredJoint = _joint[i] >= 0 && (_nodeA[i] < 0 || _nodeB[i] < 0);
                    if (pass == 0 ? !anchoredJoint : _joint[i] >= 0) continue;
                    int first = visited;
                    visited = Walk(i, visited);
                    GateLimits(bodies, data, first, visited);
                }
            // Reverse pre-order.
            for (int i = 0; i < visited / 2; i++) (_order[i], _order[visited - 1 - i]) = (_order[visited - 1 - i], _order[i]);
            // Bodies with no children in their tree: D = M, and nothing to carry in the solves.
            for (int i = 0; i < n; i++) _leaf[i] = _joint[i] < 0;
            for (int i = 0; i < n; i++)
                if (_parent[i] >= 0) _leaf[_parent[i]] = false;
            _stale = true;
        }

        /// <summary>
        /// How much heavier than the lighter body of a cone-twist joint the load it carries must
        /// be for the block to take the joint's cone and twist limits: 4.
        /// </summary>
        const float LimitMassRatio = 4f;

        // The cone and twist limits of the tree whose nodes are _order[first .. end) (pre-order)
        // stay in the block only where the joint carries a load several times its lighter body's
        // mass: row by row a limit is a spring on that body's own inertia, so a 1 kg arm under
        // 1000 kg went through its cone, and under 10-29 kg it overshot its 30 degree cone to
        // 35-45 degrees (TGS) or 65-170 (PGS) and its 10 degree twist limit to 27-38 (TGS) or
        // 75-93 (PGS); while between bodies of like mass the rows hold, and in the block they kept
        // a ragdoll pile from settling (awake after 15 s, where row by row it sleeps within
        // 3.1 s): the limits the block takes are not held by joint friction in the same pass.
        // The load a joint carries: everything on its far side from the world, in a tree hung
        // from a world anchor; in a free tree, the lighter of its two sides (a ragdoll's: 1.0-2.3
        // times the joint's lighter part, so its limits stay in the rows).
        void GateLimits(SolverBody[] bodies, JointData[] data, int first, int end)
        {
            // Subtree masses, children before parents (reverse pre-order).
            for (int k = first; k < end; k++) _subtreeMass[_order[k]] = 0f;
            for (int k = end - 1; k >= first; k--)
            {
                int node = _order[k];
                if (_joint[node] < 0) _subtreeMass[node] += 1f / bodies[_body[node]].InverseMass;
                if (_parent[node] >= 0) _subtreeMass[_parent[node]] += _subtreeMass[node];
            }
            int root = _order[first];
            bool anchored = _joint[root] >= 0;
            float total = _subtreeMass[root];
            for (int k = first; k < end; k++)
            {
                int node = _order[k];
                if (_joint[node] < 0) continue;
                ref JointData j = ref data[_joint[node]];
                if (j.Kind != JointKind.ConeTwist) continue;
                float lighter = float.MaxValue;
                if (_nodeA[node] >= 0) lighter = 1f / bodies[_body[_nodeA[node]]].InverseMass;
                if (_nodeB[node] >= 0) lighter = MathF.Min(lighter, 1f / bodies[_body[_nodeB[node]]].InverseMass);
                float carried = anchored ? _subtreeMass[node] : MathF.Min(_subtreeMass[node], total - _subtreeMass[node]);
                if (carried >= LimitMassRatio * lighter) continue;
                j.DirectLimit = 0;
                _rows[node] = JointKind.Ball;
                _dim[node] = 3;
            }
        }

        // The node of a dynamic body (made on first use); -1 for a static or kinematic one.
        int BodyNode(SolverBody[] bodies, int solverBody, ref int n)
        {
            if (solverBody == 0 || bodies[solverBody].IsDynamic != 1) return -1;
            int node = _bodyNode[solverBody];
            if (node >= 0) return node;
            _body[n] = solverBody;
            _joint[n] = -1;
            _dim[n] = 6;
            _bodyNode[solverBody] = n;
            return n++;
        }

        void Link(int bodyNode, int jointNode, int side)
        {
            if (bodyNode < 0) return;
            int e = 2 * jointNode + side;
            _next[e] = _first[bodyNode];
            _first[bodyNode] = e;
        }

        // Depth-first from root, writing the pre-order into _order from position at.
        int Walk(int root, int at)
        {
            int top = 0;
            _stack[top++] = root;
            _parent[root] = -1;
            while (top > 0)
            {
                int node = _stack[--top];
                _order[at++] = node;
                if (_joint[node] >= 0)
                {
                    Push(_nodeA[node], node, ref top);
                    Push(_nodeB[node], node, ref top);
                }
                else
                    for (int e = _first[node]; e >= 0; e = _next[e]) Push(e >> 1, node, ref top);
            }
            return at;
        }

        void Push(int node, int parent, ref int top)
        {
            if (node < 0 || _parent[node] != -2) return;
            _parent[node] = parent;
            _stack[top++] = node;
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

        /// <summary>A released one-sided row's compliance: it takes no part in the block.</summary>
        const double Released = 1e12;

        // Releases the one-sided rows whose new accumulated impulse would pull (their accumulated
        // impulse taken back from the bodies); true if any.
        bool Release(SolverBody[] bodies, JointData[] data)
        {
            bool any = false;
            double[] x = _x;
            for (int i = 0; i < _nodes; i++)
            {
                if (_joint[i] < 0 || _free[i]) continue;
                ref JointData j = ref data[_joint[i]];
                int at = Stride * i;
                ref SolverBody a = ref bodies[j.SolverA];
                ref SolverBody b = ref bodies[j.SolverB];
                if (_rows[i] == JointKind.Hinge && _dim[i] == 6)
                {
                    Vector2 s = _scale[Stride * i + 5];
                    ref AxisConstraintPart stop = ref j.DirectLimit > 0 ? ref j.Parts.Hinge.LowerLimit : ref j.Parts.Hinge.UpperLimit;
                    if (stop.Impulse + s.X * (float)x[at + 5] - s.Y * stop.Impulse >= 0f) continue;
                    // What it holds (the warm start's push) is taken back before the block is solved again.
                    Vector3 l = stop.Impulse * _axes[3 * i + 2];
                    stop.Impulse = 0;
                    if (a.IsDynamic != 0) a.ApplyAngularImpulse(l);
                    if (b.IsDynamic != 0) b.ApplyAngularImpulse(-l);
                }
                else if (_rows[i] == JointKind.Prismatic && _dim[i] == 6)
                {
                    Vector2 s = _scale[Stride * i + 5];
                    ref AxisConstraintPart stop = ref j.DirectLimit > 0 ? ref j.Parts.Prismatic.LowerLimit : ref j.Parts.Prismatic.UpperLimit;
                    if (stop.Impulse + s.X * (float)x[at + 5] - s.Y * stop.Impulse >= 0f) continue;
                    Vector3 p = stop.Impulse * _axes[3 * i + 2];
                    stop.Impulse = 0;
                    if (a.IsDynamic != 0) a.ApplyImpulse(_armA[i], p);
                    if (b.IsDynamic != 0) b.ApplyImpulse(_armB[i], -p);
                }
                else if (_rows[i] == JointKind.ConeTwist)
                {
                    // The cone and the twist limit each on their own (row 3, row 4).
                    bool released = false;
                    for (int row = 0; row < 2; row++)
                    {
                        if ((_released[i] & (1 << row)) != 0 || !ConeTwistRow(j, row)) continue;
                        Vector2 s = _scale[Stride * i + 3 + row];
                        ref AxisConstraintPart limit = ref ConeTwistLimit(ref j, row);
                        if (limit.Impulse + s.X * (float)x[at + 3 + row] - s.Y * limit.Impulse >= 0f) continue;
                        Vector3 l = limit.Impulse * _axes[3 * i + row];
                        limit.Impulse = 0;
                        if (a.IsDynamic != 0) a.ApplyAngularImpulse(l);
                        if (b.IsDynamic != 0) b.ApplyAngularImpulse(-l);
                        _released[i] |= (byte)(1 << row);
                        released = true;
                    }
                    if (released) any = true;
                    continue;
                }
                else if (_rows[i] == JointKind.Distance && j.MinLength != j.MaxLength)
                {
                    Vector2 s = _scale[Stride * i];
                    ref AxisConstraintPart rope = ref j.Parts.Distance.UpperLimit;
                    if (rope.Impulse + s.X * (float)x[at] - s.Y * rope.Impulse >= 0f) continue;
                    Vector3 p = rope.Impulse * _axes[3 * i];
                    rope.Impulse = 0;
                    if (a.IsDynamic != 0) a.ApplyImpulse(_armA[i], p);
                    if (b.IsDynamic != 0) b.ApplyImpulse(_armB[i], -p);
                }
                else continue;
                _free[i] = true;
                any = true;
            }
            return any;
        }

        // The right-hand sides (J v + bias) and the block solve: x = -A^-1 (J v + bias).
        void Compute(SolverBody[] bodies, JointData[] data, in Softness soft, float h, bool useBias)
        {
            double[] x = _x;
            for (int i = 0; i < _nodes; i++)
            {
                int at = Stride * i;
                if (_joint[i] < 0)
                {
                    for (int k = 0; k < 6; k++) x[at + k] = 0;
                    continue;
                }
                ref JointData j = ref data[_joint[i]];
                ref SolverBody a = ref bodies[j.SolverA];
                ref SolverBody b = ref bodies[j.SolverB];
                Vector3 jv = b.PointVelocity(_armB[i]) - a.PointVelocity(_armA[i]);
                float massScale = 1, impulseScale = 0;
                if (_rows[i] == JointKind.Prismatic)
                {
                    // Two rows across the slide axis (A's arm reaching to B's anchor, as
                    // PrismaticJointSolver sets them), each with its own bias, then the lock.
                    Vector3 rel = b.PointVelocity(_armB[i]) - a.PointVelocity(_armA[i]);
                    for (int r = 0; r < 2; r++)
                    {
                        float v = Vector3.Dot(_axes[3 * i + r], rel);
                        massScale = 1;
                        impulseScale = 0;
                        if (useBias) v += soft.Bias(r == 0 ? _gap[i].X : _gap[i].Y, out massScale, out impulseScale);
                        _scale[Stride * i + r] = new Vector2(massScale, impulseScale);
                        x[at + r] = v;
                    }
                    Vector3 wl = b.AngularVelocity - a.AngularVelocity;
                    massScale = 1;
                    impulseScale = 0;
                    if (useBias) wl += soft.Bias(_error[i], out massScale, out impulseScale);
                    for (int r = 2; r < 5; r++) _scale[Stride * i + r] = new Vector2(massScale, impulseScale);
                    x[at + 2] = wl.X;
                    x[at + 3] = wl.Y;
                    x[at + 4] = wl.Z;
                    if (_dim[i] == 6)
                    {
                        // The limit: speculative while still ahead (a contact's gap: it stops only
                        // what would pass it within the substep), soft and biased on or past it.
                        // Scaled as the rows across the axis are (the node's rows are solved together).
                        float v = Vector3.Dot(_axes[3 * i + 2], rel), limit = _gap[i].Z;
                        Vector2 across = _scale[Stride * i];
                        if (limit > 0) v += limit / h;
                        else if (useBias) v += soft.Bias(limit, out _, out _);
                        _scale[Stride * i + 5] = across;
                        x[at + 5] = v;
                    }
                    continue;
                }
                if (_rows[i] == JointKind.Distance)
                {
                    // The length row: J v = n . (the anchors' relative velocity), error |d| - L.
                    float v = Vector3.Dot(_axes[3 * i], jv);
                    if (useBias) v += soft.Bias(_error[i].X, out massScale, out impulseScale);
                    _scale[Stride * i] = new Vector2(massScale, impulseScale);
                    x[at] = v;
                    x[at + 1] = Vector3.Dot(_axes[3 * i + 1], jv);
                    x[at + 2] = Vector3.Dot(_axes[3 * i + 2], jv);
                    x[at + 3] = x[at + 4] = x[at + 5] = x[at + 6] = 0;
                    // The tilt rows of each held end: J v = e_k . w of that end's body.
                    for (int side = 0; side < 2; side++)
                    {
                        if ((_tilt[i] & (1 << side)) == 0) continue;
                        Vector3 spin = side == 1 ? b.AngularVelocity : a.AngularVelocity;
                        x[at + 3 + 2 * side] = Vector3.Dot(_axes[3 * i + 1], spin);
                        x[at + 4 + 2 * side] = Vector3.Dot(_axes[3 * i + 2], spin);
                    }
                    continue;
                }
                if (useBias) jv += soft.Bias(_gap[i], out massScale, out impulseScale);
                for (int r = 0; r < 3; r++) _scale[Stride * i + r] = new Vector2(massScale, impulseScale);
                x[at] = jv.X;
                x[at + 1] = jv.Y;
                x[at + 2] = jv.Z;
                int rows = _dim[i] - 3;
                if (rows == 0) continue;
                if (_rows[i] == JointKind.ConeTwist)
                {
                    // The cone (row 3) and a twist limit (row 4): speculative while still ahead (each
                    // stops only what would pass it within the substep), soft and biased on or past
                    // it; scaled as the anchor rows. A row the joint does not rest on is zero and released.
                    Vector3 wr = b.AngularVelocity - a.AngularVelocity;
                    for (int row = 0; row < 2; row++)
                    {
                        float limit = row == 0 ? _error[i].X : _error[i].Y, v = Vector3.Dot(_axes[3 * i + row], wr);
                        if (limit > 0) v += limit / h;
                        else if (useBias) v += soft.Bias(limit, out _, out _);
                        _scale[Stride * i + 3 + row] = new Vector2(massScale, impulseScale);
                        x[at + 3 + row] = v;
                    }
                    continue;
                }
                // Rotation rows: J v = u . (wB - wA); the bias as the kind's own rows ask it (the
                // error vector capped as one, so the cap keeps its direction).
                Vector3 w = b.AngularVelocity - a.AngularVelocity;
                Vector3 bias = Vector3.Zero;
                massScale = 1;
                impulseScale = 0;
                // A stop still ahead (error > 0) is speculative, as a contact's gap: the hinge may
                // close it within the substep, and the row stops only what would pass it.
                Vector3 error = _error[i];
                float ahead = _rows[i] == JointKind.Hinge && rows == 3 && error.Z > 0 ? error.Z : 0;
                if (ahead > 0) error.Z = 0;
                if (useBias)
                {
                    Vector3 raw = soft.BiasRate * error;
                    soft.Capped(raw.Length(), out float k, out massScale, out impulseScale);
                    bias = k * raw;
                }
                if (ahead > 0) bias.Z = ahead / h;
                for (int r = 0; r < rows; r++)
                {
                    x[at + 3 + r] = Vector3.Dot(_axes[3 * i + r], w) + (r == 0 ? bias.X : r == 1 ? bias.Y : bias.Z);
                    _scale[Stride * i + 3 + r] = new Vector2(massScale, impulseScale);
                }
            }
            // Forward: z_i = D_i^-1 y_i, y_p -= H_ip^T z_i (children first).
            double[] t = _scratch;
            for (int n = 0; n < _nodes; n++)
            {
                int i = _order[n], d = Dim(i), at = Stride * i, m = Block * i;
                if (_leaf[i]) continue; // a childless body: y = 0, so z = 0 and nothing reaches its parent
                for (int r = 0; r < d; r++)
                {
                    double sum = 0;
                    for (int c = 0; c < d; c++) sum += _dinv[m + Stride * r + c] * x[at + c];
                    t[r] = sum;
                }
                for (int r = 0; r < d; r++) x[at + r] = t[r];
                int p = _parent[i];
                if (p < 0) continue;
                int dp = Dim(p), ap = Stride * p;
                for (int c = 0; c < dp; c++)
                {
                    double sum = 0;
                    for (int k = 0; k < d; k++) sum += _h[m + Stride * k + c] * t[k];
                    x[ap + c] -= sum;
                }
            }
            // Backward: x_i = z_i - L_i x_p (parents first).
            for (int n = _nodes - 1; n >= 0; n--)
            {
                int i = _order[n], p = _parent[i];
                if (p < 0) continue;
                int d = Dim(i), dp = Dim(p), at = Stride * i, ap = Stride * p, m = Block * i;
                for (int r = 0; r < d; r++)
                {
                    double sum = 0;
                    for (int c = 0; c < dp; c++) sum += _l[m + Stride * r + c] * x[ap + c];
                    x[at + r] -= sum;
                }
            }
        }

        // Applies the block's impulses to the rows and the bodies.
        void Apply(SolverBody[] bodies, JointData[] data)
        {
            double[] x = _x;
            if (_sum.Length < 6 * _nodes) _sum = new double[Math.Max(6 * _nodes, 2 * _sum.Length)];
            Array.Clear(_sum, 0, 6 * _nodes);
            // x holds the rigid impulses -A^-1 (J v + bias). The soft step scales them as a single
            // row's: dLambda = massScale x - impulseScale lambda, so a biased row is a spring on the
            // tree's true effective mass A^-1 (the load's, not the link's). Applied row by row.
            for (int i = 0; i < _nodes; i++)
            {
                if (_joint[i] < 0) continue;
                int at = Stride * i;
                ref JointData j = ref data[_joint[i]];
                Vector2 s = _scale[Stride * i];
                if (_rows[i] == JointKind.Prismatic)
                {
                    ref PrismaticJointParts slide = ref j.Parts.Prismatic;
                    float d1 = s.X * (float)x[at] - s.Y * slide.Perp1.Impulse;
                    Vector2 s2 = _scale[Stride * i + 1];
                    float d2 = s2.X * (float)x[at + 1] - s2.Y * slide.Perp2.Impulse;
                    slide.Perp1.Impulse += d1;
                    slide.Perp2.Impulse += d2;
                    Vector3 across = d1 * _axes[3 * i] + d2 * _axes[3 * i + 1];
                    if (_dim[i] == 6 && !_free[i])
                    {
                        // The limit it rests on: it may only push away from it.
                        ref AxisConstraintPart stop = ref j.DirectLimit > 0 ? ref slide.LowerLimit : ref slide.UpperLimit;
                        Vector2 s5 = _scale[Stride * i + 5];
                        float d5 = s5.X * (float)x[at + 5] - s5.Y * stop.Impulse;
                        if (stop.Impulse + d5 < 0f) d5 = -stop.Impulse;
                        stop.Impulse += d5;
                        across += d5 * _axes[3 * i + 2];
                    }
                    Vector2 s3 = _scale[Stride * i + 2];
                    Vector3 turn = s3.X * new Vector3((float)x[at + 2], (float)x[at + 3], (float)x[at + 4]) - s3.Y * slide.Lock.Impulse;
                    slide.Lock.Impulse += turn;
                    Push(_nodeA[i], _armA[i], -across, -turn);
                    Push(_nodeB[i], _armB[i], across, turn);
                    continue;
                }
                if (_rows[i] == JointKind.Distance)
                {
                    bool rope = j.MinLength != j.MaxLength;
                    ref AxisConstraintPart length = ref rope ? ref j.Parts.Distance.UpperLimit : ref j.Parts.Distance.Length;
                    float dl = s.X * (float)x[at] - s.Y * length.Impulse;
                    if (rope && length.Impulse + dl < 0f) dl = -length.Impulse; // a rope only pulls
                    length.Impulse += dl;
                    // The geometric stiffness rows' impulses as they are (compliant, unbiased, not kept),
                    // but where tilt rows hold an end: then all of them scaled as the length row's
                    // rigid impulse is (massScale). They were solved against that rigid impulse, and
                    // the soft step delivers only its scaled part: applied whole they pushed a light bar
                    // against a pull it no longer had, and five 1 kg bars under 1000 kg burst faster
                    // than without them (consistent, they hold).
                    float across = _tilt[i] != 0 ? s.X : 1f;
                    Vector3 p = dl * _axes[3 * i] + across * ((float)x[at + 1] * _axes[3 * i + 1] + (float)x[at + 2] * _axes[3 * i + 2]);
                    Vector3 turnA = across * ((float)x[at + 3] * _axes[3 * i + 1] + (float)x[at + 4] * _axes[3 * i + 2]);
                    Vector3 turnB = across * ((float)x[at + 5] * _axes[3 * i + 1] + (float)x[at + 6] * _axes[3 * i + 2]);
                    Push(_nodeA[i], _armA[i], -p, (_tilt[i] & 1) != 0 ? turnA : Vector3.Zero);
                    Push(_nodeB[i], _armB[i], p, (_tilt[i] & 2) != 0 ? turnB : Vector3.Zero);
                    continue;
                }
                ref PointConstraintPart point = ref Point(ref j);
                Vector3 impulse = s.X * new Vector3((float)x[at], (float)x[at + 1], (float)x[at + 2]) - s.Y * point.Impulse;
                point.Impulse += impulse;
                if (_dim[i] == 3)
                {
                    Push(_nodeA[i], _armA[i], -impulse, Vector3.Zero);
                    Push(_nodeB[i], _armB[i], impulse, Vector3.Zero);
                    continue;
                }
                Vector3 l;
                s = _scale[Stride * i + 3];
                if (_rows[i] == JointKind.ConeTwist)
                {
                    // The cone and the twist limit it rests on: each may only push back within its limit.
                    l = Vector3.Zero;
                    for (int row = 0; row < 2; row++)
                    {
                        if ((_released[i] & (1 << row)) != 0 || !ConeTwistRow(j, row)) continue;
                        ref AxisConstraintPart limit = ref ConeTwistLimit(ref j, row);
                        Vector2 sr = _scale[Stride * i + 3 + row];
                        float d = sr.X * (float)x[at + 3 + row] - sr.Y * limit.Impulse;
                        if (limit.Impulse + d < 0f) d = -limit.Impulse;
                        limit.Impulse += d;
                        l += d * _axes[3 * i + row];
                    }
                }
                else if (_rows[i] == JointKind.Fixed)
                {
                    ref RotationLockPart lockPart = ref j.Parts.Fixed.Lock;
                    Vector3 d = s.X * new Vector3((float)x[at + 3], (float)x[at + 4], (float)x[at + 5]) - s.Y * lockPart.Impulse;
                    lockPart.Impulse += d;
                    l = d;
                }
                else
                {
                    ref HingeRotationPart hinge = ref j.Parts.Hinge.Rotation;
                    float d1 = s.X * (float)x[at + 3] - s.Y * hinge.Impulse1;
                    float d2 = s.X * (float)x[at + 4] - s.Y * hinge.Impulse2;
                    hinge.Impulse1 += d1;
                    hinge.Impulse2 += d2;
                    l = d1 * _axes[3 * i] + d2 * _axes[3 * i + 1];
                    if (_dim[i] == 6)
                    {
                        // The limit it rests on: it may only push away from the stop.
                        ref AxisConstraintPart stop = ref j.DirectLimit > 0 ? ref j.Parts.Hinge.LowerLimit : ref j.Parts.Hinge.UpperLimit;
                        float d3 = s.X * (float)x[at + 5] - s.Y * stop.Impulse;
                        if (stop.Impulse + d3 < 0f) d3 = -stop.Impulse;
                        stop.Impulse += d3;
                        l += d3 * _axes[3 * i + 2];
                    }
                }
                Push(_nodeA[i], _armA[i], -impulse, -l);
                Push(_nodeB[i], _armB[i], impulse, l);
            }
            // Each body's velocity changes once, from its impulses summed in double: around a
            // light body between heavy ones they cancel to a small remainder, which, applied
            // joint by joint in float, came out at the float spacing of the large terms (a 1 kg arm
            // under 1e5 kg on a cone and a twist limit took 1 rad/s of noise each step and tore loose).
            for (int i = 0; i < _nodes; i++)
            {
                if (_joint[i] >= 0) continue;
                int at = 6 * i;
                ref SolverBody body = ref bodies[_body[i]];
                body.LinearVelocity += body.InverseMass * new Vector3((float)_sum[at], (float)_sum[at + 1], (float)_sum[at + 2]);
                body.AngularVelocity += body.InverseInertia * new Vector3((float)_sum[at + 3], (float)_sum[at + 4], (float)_sum[at + 5]);
            }
        }

        // Adds an impulse p at arm r and an angular impulse l to body node `node`'s sums (nothing for -1, a static or kinematic body).
        void Push(int node, Vector3 r, Vector3 p, Vector3 l)
        {
            if (node < 0) return;
            int at = 6 * node;
            double[] sum = _sum;
            sum[at] += p.X;
            sum[at + 1] += p.Y;
            sum[at + 2] += p.Z;
            sum[at + 3] += (double)r.Y * p.Z - (double)r.Z * p.Y + l.X;
            sum[at + 4] += (double)r.Z * p.X - (double)r.X * p.Z + l.Y;
            sum[at + 5] += (double)r.X * p.Y - (double)r.Y * p.X + l.Z;
        }

        int Dim(int node) => _dim[node];

        /// <summary>The anchor rows of a ball, hinge, fixed or cone-twist joint.</summary>
        static ref PointConstraintPart Point(ref JointData j)
        {
            switch (j.Kind)
            {
                case JointKind.Ball: return ref j.Parts.Ball.Point;
                case JointKind.Hinge: return ref j.Parts.Hinge.Point;
                case JointKind.Fixed: return ref j.Parts.Fixed.Point;
                default: return ref j.Parts.ConeTwist.Point;
            }
        }

        // Whether a cone-twist joint's block holds row 3 + row (0: the cone, 1: a twist limit).
        static bool ConeTwistRow(in JointData j, int row) => (j.DirectLimit & (row == 0 ? ConeRow : TwistLowerRow | TwistUpperRow)) != 0;

        // The limit part behind a cone-twist joint's block row 3 + row.
        static ref AxisConstraintPart ConeTwistLimit(ref JointData j, int row)
        {
            if (row == 0) return ref j.Parts.ConeTwist.Cone;
            if ((j.DirectLimit & TwistLowerRow) != 0) return ref j.Parts.ConeTwist.LowerLimit;
            return ref j.Parts.ConeTwist.UpperLimit;
        }

        // Block LDL^T in elimination order: D_i = H_ii - sum over children c of H_ci^T D_c^-1 H_ci,
        // L_i = D_i^-1 H_ip. Blocks are Stride x Stride slots holding d x d or d x dp entries.
        bool Factor(SolverBody[] bodies, JointData[] data, float step)
        {
            double[] dm = _dinv;
            for (int i = 0; i < _nodes; i++)
            {
                int m = Block * i;
                for (int k = 0; k < Block; k++) dm[m + k] = 0;
                if (_joint[i] >= 0)
                {
                    ref JointData j = ref data[_joint[i]];
                    var g = new JointGeometry(j, bodies[j.SolverA], bodies[j.SolverB]);
                    _armA[i] = g.ArmA;
                    _armB[i] = g.ArmB;
                    _gap[i] = g.Gap;
                    if (_rows[i] == JointKind.Prismatic)
                    {
                        SliderRows(g.FrameA, g.Gap, out _axes[3 * i], out _axes[3 * i + 1], out float c1, out float c2);
                        _armA[i] = g.ArmA + g.Gap; // the slide axis turns with A: A's arm reaches B's anchor
                        _error[i] = RotationLockPart.Error(g.FrameA, g.FrameB);
                        // A limit it rests on: one more row along the slide axis (as the joint's own
                        // limit rows: +axis for the lower, -axis for the upper), its error toward it.
                        float limit = 0;
                        if (j.DirectLimit != 0)
                        {
                            Vector3 axis = Vector3.Transform(Vector3.UnitX, g.FrameA);
                            float slide = Vector3.Dot(axis, g.Gap);
                            _axes[3 * i + 2] = j.DirectLimit > 0 ? axis : -axis;
                            limit = j.DirectLimit > 0 ? slide - j.Lower : j.Upper - slide;
                            if (_free[i]) dm[m + At(5, 5)] = -Released;
                        }
                        _gap[i] = new Vector3(c1, c2, limit);
                    }
                    else if (_rows[i] == JointKind.Distance)
                    {
                        // As DistanceJointSolver builds its row: along the anchors' line (a rope's
                        // upper limit row against it, so that a positive impulse pulls).
                        float length = g.Gap.Length();
                        Vector3 n = length > 1e-6f ? g.Gap / length : Vector3.UnitY;
                        bool rope = j.MinLength != j.MaxLength;
                        _axes[3 * i] = rope ? -n : n;
                        _error[i] = new Vector3(rope ? j.MaxLength - length : length - j.MinLength, 0, 0);
                        // Two rows across the rod: its geometric stiffness, implicit (Tournier et al.
                        // 2015, "Stable Constrained Dynamics"). A rod of length L under tension T
                        // resists its ends' sideways motion as a spring of T / L; taken only
                        // explicitly (the row's direction turning from one substep to the next)
                        // that spring outruns the substep where a light body sits between tensed
                        // rods: a 1000 kg load swung 0.3 rad on one 1 kg link between two rods fell
                        // 190 m at 4 substeps (stable from 8). Implicit, it is compliance
                        // L / (T h^2) (impulse per velocity) on the rows, no bias, nothing kept.
                        Tangents(n, out _axes[3 * i + 1], out _axes[3 * i + 2]);
                        float tension = MathF.Abs(rope ? j.Parts.Distance.UpperLimit.Impulse : j.Parts.Distance.Length.Impulse) / step;
                        // Only where that spring is stiff for the lighter body at this substep
                        // (K h^2 / m above 0.1, its frequency times h above 0.3): the implicit rows
                        // also damp sideways motion, the swing too (the load above keeps 93 % of
                        // a 0.3 rad swing after 10 s, where ball joints in the rods' place keep
                        // all of it), and a pendulum on a rod (Newton's cradle, K h^2 / m = 1e-4)
                        // should keep all of it. Tried and dropped: taking only the stiffness
                        // beyond m / h^2 implicit, or resisting only the change in sideways
                        // velocity since the last factorisation (no damping): the chain burst again.
                        float lighter = MathF.Max(bodies[j.SolverA].InverseMass, bodies[j.SolverB].InverseMass);
                        double stiffness = tension / Math.Max(length, 1e-6);
                        double compliance = stiffness * step * step * lighter > 0.1 ? 1.0 / (stiffness * step * step) : 1e12;
                        dm[m + At(1, 1)] = -compliance;
                        dm[m + At(2, 2)] = -compliance;
                        // Two tilt rows per end: the turning of its body against the rod's line, whose
                        // stiffness under the pull is explicit otherwise (see Tilt).
                        float pull = (rope ? j.Parts.Distance.UpperLimit.Impulse : -j.Parts.Distance.Length.Impulse) / step;
                        _tilt[i] = 0;
                        for (int side = 0; side < 2; side++)
                        {
                            double tilt = Tilt(bodies, j, side == 1, side == 1 ? _armB[i] : _armA[i], n, _axes[3 * i + 1], _axes[3 * i + 2], length, pull, step);
                            if (tilt < 1e12) _tilt[i] |= (byte)(1 << side);
                            dm[m + At(3 + 2 * side, 3 + 2 * side)] = -tilt;
                            dm[m + At(4 + 2 * side, 4 + 2 * side)] = -tilt;
                        }
                        // A rod no end of which is held (the common case: a light pull, or arms at
                        // the centres) keeps its three rows, so it costs what it did without tilt rows:
                        // the slots stay Stride wide, and rows 3-6 are zero and uncoupled anyway.
                        _dim[i] = _tilt[i] != 0 ? 7 : 3;
                        if (_free[i]) // slack: no tension, no stiffness
                            for (int row = 0; row < 7; row++) dm[m + At(row, row)] = -Released;
                    }
                    else if (_rows[i] == JointKind.ConeTwist)
                    {
                        // The cone row, as ConeTwistJointSolver's: J = [0, -s] on B (s the swing
                        // axis), its error the room left in the cone (negative past it).
                        ConeSwing(g.FrameA, g.FrameB, out Vector3 swingAxis, out float swing);
                        // The twist limit, as its rows: +t for the lower (error twist + limit), -t for the upper.
                        Vector3 t = TwistAxis(g.FrameA, g.FrameB);
                        float twist = JointSolver.TwistAngle(g.FrameA, g.FrameB);
                        bool lower = (j.DirectLimit & TwistLowerRow) != 0;
                        _axes[3 * i] = ConeTwistRow(j, 0) ? -swingAxis : Vector3.Zero;
                        _axes[3 * i + 1] = !ConeTwistRow(j, 1) ? Vector3.Zero : lower ? t : -t;
                        _error[i] = new Vector3(j.ConeAngle - swing, lower ? twist + j.TwistAngle : j.TwistAngle - twist, 0);
                        for (int row = 0; row < 2; row++)
                            if ((_released[i] & (1 << row)) != 0 || !ConeTwistRow(j, row)) dm[m + At(3 + row, 3 + row)] = -Released;
                    }
                    else if (_rows[i] == JointKind.Fixed)
                    {
                        _error[i] = RotationLockPart.Error(g.FrameA, g.FrameB);
                        _axes[3 * i] = Vector3.UnitX;
                        _axes[3 * i + 1] = Vector3.UnitY;
                        _axes[3 * i + 2] = Vector3.UnitZ;
                    }
                    else if (_rows[i] == JointKind.Hinge)
                    {
                        HingeRows(g.FrameA, g.FrameB, out _axes[3 * i], out _axes[3 * i + 1], out float e1, out float e2);
                        // A limit it rests on: one more row about the axis (as HingeJointSolver's
                        // limit rows: +a1 for the lower, -a1 for the upper), its error toward the limit.
                        float limit = 0;
                        if (j.DirectLimit != 0)
                        {
                            Vector3 axis = Vector3.Transform(Vector3.UnitX, g.FrameA);
                            float angle = JointSolver.TwistAngle(g.FrameA, g.FrameB);
                            _axes[3 * i + 2] = j.DirectLimit > 0 ? axis : -axis;
                            limit = j.DirectLimit > 0 ? angle - j.Lower : j.Upper - angle;
                        }
                        _error[i] = new Vector3(e1, e2, limit);
                        if (_free[i] && j.DirectLimit != 0) dm[m + At(5, 5)] = -Released;
                    }
                    continue;
                }
                if (_leaf[i]) continue; // D = M: its inverse is written below from the solver body
                ref SolverBody body = ref bodies[_body[i]];
                double mass = 1.0 / body.InverseMass;
                dm[m] = dm[m + At(1, 1)] = dm[m + At(2, 2)] = mass;
                if (!Invert3(body.InverseInertia, dm, m + At(3, 3))) return false;
            }
            for (int n = 0; n < _nodes; n++)
            {
                int i = _order[n], d = Dim(i), m = Block * i;
                if (_joint[i] < 0 && _leaf[i])
                {
                    // A body with no children: D = M, whose inverse the solver body holds.
                    ref SolverBody body = ref bodies[_body[i]];
                    for (int k = 0; k < Block; k++) dm[m + k] = 0;
                    dm[m] = dm[m + At(1, 1)] = dm[m + At(2, 2)] = body.InverseMass;
                    Mat3 ii = body.InverseInertia;
                    dm[m + At(3, 3)] = ii.C0.X; dm[m + At(3, 4)] = ii.C1.X; dm[m + At(3, 5)] = ii.C2.X;
                    dm[m + At(4, 3)] = ii.C0.Y; dm[m + At(4, 4)] = ii.C1.Y; dm[m + At(4, 5)] = ii.C2.Y;
                    dm[m + At(5, 3)] = ii.C0.Z; dm[m + At(5, 4)] = ii.C1.Z; dm[m + At(5, 5)] = ii.C2.Z;
                }
                else if (!InvertDefinite(dm, m, d, _joint[i] >= 0 ? -1 : 1)) return false;
                int p = _parent[i];
                if (p < 0) continue;
                int dp = Dim(p), mp = Block * p;
                double[] h = _h;
                for (int k = 0; k < Block; k++) h[m + k] = 0;
                if (_joint[i] >= 0) MinusJacobian(i, p, h, m, transpose: false);
                else MinusJacobian(p, i, h, m, transpose: true);
                // L_i = D_i^-1 H_ip; D_p -= H_ip^T L_i.
                for (int r = 0; r < d; r++)
                    for (int c = 0; c < dp; c++)
                    {
                        double sum = 0;
                        for (int k = 0; k < d; k++) sum += dm[m + Stride * r + k] * h[m + Stride * k + c];
                        _l[m + Stride * r + c] = sum;
                    }
                // H^T D^-1 H is symmetric: the upper triangle, mirrored.
                for (int r = 0; r < dp; r++)
                    for (int c = r; c < dp; c++)
                    {
                        double sum = 0;
                        for (int k = 0; k < d; k++) sum += h[m + Stride * k + r] * _l[m + Stride * k + c];
                        dm[mp + Stride * r + c] -= sum;
                        if (c != r) dm[mp + Stride * c + r] -= sum;
                    }
            }
            return true;
        }

        // -J of joint node j against body node b: -s [I, -[r]] = [-s I, s [r]], s = +1 on B's side,
        // -1 on A's ([r] w = r x w). Written as a 3x6 block, or transposed as 6x3, at h[at] (row stride Stride).
        void MinusJacobian(int j, int b, double[] h, int at, bool transpose)
        {
            bool sideB = _nodeB[j] == b;
            double s = sideB ? 1 : -1;
            Vector3 r = sideB ? _armB[j] : _armA[j];
            if (_rows[j] == JointKind.Prismatic)
            {
                // Rows 0-1: -J = -s [p, r x p] across the slide axis; rows 2-4: -J = [0, -s e_k].
                for (int row = 0; row < 2; row++) LinearRow(h, at, row, s, _axes[3 * j + row], r, transpose);
                for (int k = 0; k < 3; k++)
                {
                    int row = 2 + k, c = 3 + k;
                    if (transpose) h[at + Stride * c + row] = -s;
                    else h[at + Stride * row + c] = -s;
                }
                // Row 5, a limit it rests on: -J = -s [a, r x a] along the slide axis.
                if (_dim[j] == 6) LinearRow(h, at, 5, s, _axes[3 * j + 2], r, transpose);
                return;
            }
            if (_rows[j] == JointKind.Distance)
            {
                // Along the rod and the two across it: -J = -s [a, r x a].
                for (int row = 0; row < 3; row++) LinearRow(h, at, row, s, _axes[3 * j + row], r, transpose);
                // The tilt rows of this body's end, if held: -J = [0, -e_k] (the other end's rows stay
                // zero against this body, and unheld rows zero and fully compliant).
                int side = sideB ? 1 : 0;
                if ((_tilt[j] & (1 << side)) == 0) return;
                int first = 3 + 2 * side;
                for (int k = 0; k < 2; k++)
                {
                    Vector3 e = _axes[3 * j + 1 + k];
                    for (int c = 0; c < 3; c++)
                    {
                        double v = c == 0 ? e.X : c == 1 ? e.Y : e.Z;
                        if (transpose) h[at + Stride * (3 + c) + first + k] = -v;
                        else h[at + Stride * (first + k) + 3 + c] = -v;
                    }
                }
                return;
            }
            Span<double> block = stackalloc double[18];
            block[0] = -s; block[7] = -s; block[14] = -s;
            // s [r]: rows [0, -rz, ry], [rz, 0, -rx], [-ry, rx, 0] in columns 3..5.
            block[4] = -s * r.Z; block[5] = s * r.Y;
            block[9] = s * r.Z; block[11] = -s * r.X;
            block[15] = -s * r.Y; block[16] = s * r.X;
            for (int row = 0; row < 3; row++)
                for (int col = 0; col < 6; col++)
                {
                    double v = block[6 * row + col];
                    if (transpose) h[at + Stride * col + row] = v;
                    else h[at + Stride * row + col] = v;
                }
            // Rotation rows: -J = [0, -s u].
            for (int row = 3; row < _dim[j]; row++)
            {
                Vector3 u = _axes[3 * j + row - 3];
                for (int c = 0; c < 3; c++)
                {
                    double v = -s * (c == 0 ? u.X : c == 1 ? u.Y : u.Z);
                    if (transpose) h[at + Stride * (3 + c) + row] = v;
                    else h[at + Stride * row + 3 + c] = v;
                }
            }
        }

        // One linear row of -J, -s [a, r x a], at row `row` of the 3x6 block at h[at] (or column `row` of its 6x3 transpose).
        static void LinearRow(double[] h, int at, int row, double s, Vector3 a, Vector3 r, bool transpose)
        {
            Vector3 ra = Vector3.Cross(r, a);
            for (int c = 0; c < 6; c++)
            {
                double v = -s * (c == 0 ? a.X : c == 1 ? a.Y : c == 2 ? a.Z : c == 3 ? ra.X : c == 4 ? ra.Y : ra.Z);
                if (transpose) h[at + Stride * c + row] = v;
                else h[at + Stride * row + c] = v;
            }
        }

        /// <summary>
        /// The compliance of the two tilt rows of one end of a rod (B's with <paramref name="sideB"/>),
        /// 1e12 where they stay out. A body pulled at an arm r by a rod under tension T (force T u,
        /// u toward the rod's other end) hangs from that anchor like a pendulum in a field T: turned
        /// by a small angle about an axis across the rod, its anchor moves in by r angle^2 / 2 and the
        /// energy rises by T (u . r) angle^2 / 2: the second-order term of the anchor's rotation,
        /// the rod's geometric stiffness besides T / L across it (the Hessian of T C in the body's
        /// rotation, Tournier et al. 2015). For a light bar under a heavy load it outruns the
        /// substep: a 1 kg, 0.5 m bar between two 0.1 m rods under 1000 kg turns at about 480 rad/s,
        /// and five of them swung 0.3 rad burst at 4 substeps (40 m off in 10 s; 8 substeps held).
        /// Implicit, as the rows across: rows J = [0, e_k] on the end's body, compliance
        /// 1 / (k h^2), k = T (u . r), where k h^2 I^-1 is above 0.1. Like every implicit stiffness
        /// they damp what turns the body, the swing too. Tried: measuring the turning against the
        /// rod's line instead (zero for a rigid swing, so undamped) held the five bars to 1e4 kg, but
        /// is not the Hessian (its lateral part is (u . r) / L times too stiff), and the explicit
        /// remainder burst the chain from 1e5 kg; one end per rod (the block then held at most six
        /// rows a joint) burst it from 3000 kg.
        /// </summary>
        static double Tilt(SolverBody[] bodies, in JointData j, bool sideB, Vector3 arm, Vector3 n, Vector3 t1, Vector3 t2, float length, float pull, float h)
        {
            if (!(pull > 0) || length < 1e-3f) return 1e12;
            ref SolverBody body = ref bodies[sideB ? j.SolverB : j.SolverA];
            if (body.IsDynamic != 1) return 1e12;
            double stiffness = pull * (double)(sideB ? -Vector3.Dot(n, arm) : Vector3.Dot(n, arm));
            if (!(stiffness > 0)) return 1e12;
            Mat3 ii = body.InverseInertia;
            double ratio = stiffness * h * h * 0.5 * (Vector3.Dot(t1, ii * t1) + Vector3.Dot(t2, ii * t2));
            return ratio > 0.1 ? 1.0 / (stiffness * h * h) : 1e12;
        }

        /// <summary>Two unit vectors perpendicular to unit <paramref name="n"/> and to each other.</summary>
        static void Tangents(Vector3 n, out Vector3 t1, out Vector3 t2)
        {
            Vector3 other = MathF.Abs(n.X) < 0.57f ? Vector3.UnitX : Vector3.UnitY;
            t1 = Vector3.Normalize(Vector3.Cross(n, other));
            t2 = Vector3.Cross(n, t1);
        }

        /// <summary>
        /// A prismatic joint's rows across its slide axis (as <see cref="PrismaticJointSolver"/>
        /// builds them): A's frame y and z axes and the gap's components along them.
        /// </summary>
        static void SliderRows(Quaternion fA, Vector3 gap, out Vector3 p1, out Vector3 p2, out float c1, out float c2)
        {
            p1 = Vector3.Transform(Vector3.UnitY, fA);
            p2 = Vector3.Transform(Vector3.UnitZ, fA);
            c1 = Vector3.Dot(p1, gap);
            c2 = Vector3.Dot(p2, gap);
        }

        /// <summary>
        /// A hinge's two rotation rows (as <see cref="HingeJointSolver"/> builds them): with a1 the
        /// axis in A's frame and b2, c2 B's frame axes across it, u1 = b2 x a1, u2 = c2 x a1 and the
        /// errors a1.b2, a1.c2.
        /// </summary>
        static void HingeRows(Quaternion fA, Quaternion fB, out Vector3 u1, out Vector3 u2, out float e1, out float e2)
        {
            Vector3 axis = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 b2 = Vector3.Transform(Vector3.UnitY, fB);
            Vector3 c2 = Vector3.Transform(Vector3.UnitZ, fB);
            u1 = Vector3.Cross(b2, axis);
            u2 = Vector3.Cross(c2, axis);
            e1 = Vector3.Dot(axis, b2);
            e2 = Vector3.Dot(axis, c2);
        }

        // The inverse of a 3x3 (float) into the 3x3 corner at m[at] (stride Stride), in double.
        static bool Invert3(in Mat3 a, double[] m, int at)
        {
            double a00 = a.C0.X, a01 = a.C1.X, a02 = a.C2.X;
            double a10 = a.C0.Y, a11 = a.C1.Y, a12 = a.C2.Y;
            double a20 = a.C0.Z, a21 = a.C1.Z, a22 = a.C2.Z;
            double c00 = a11 * a22 - a12 * a21, c01 = a02 * a21 - a01 * a22, c02 = a01 * a12 - a02 * a11;
            double det = a00 * c00 + a10 * c01 + a20 * c02;
            if (!(Math.Abs(det) > 0) || double.IsInfinity(det)) return false;
            double inv = 1.0 / det;
            m[at] = c00 * inv; m[at + 1] = c01 * inv; m[at + 2] = c02 * inv;
            m[at + Stride] = (a12 * a20 - a10 * a22) * inv; m[at + Stride + 1] = (a00 * a22 - a02 * a20) * inv; m[at + Stride + 2] = (a02 * a10 - a00 * a12) * inv;
            m[at + 2 * Stride] = (a10 * a21 - a11 * a20) * inv; m[at + 2 * Stride + 1] = (a01 * a20 - a00 * a21) * inv; m[at + 2 * Stride + 2] = (a00 * a11 - a01 * a10) * inv;
            return true;
        }

        // In-place inverse of the symmetric d x d block at m[at] (stride Stride), positive definite
        // times sign (a body's block is positive definite, a joint's negative): Cholesky
        // sign D = L L^T, then D^-1 = sign L^-T L^-1. About a third of Gauss-Jordan's work; false
        // (nothing written) when the block is not definite to working precision.
        static bool InvertDefinite(double[] m, int at, int d, double sign)
        {
            Span<double> l = stackalloc double[Block];
            Span<double> li = stackalloc double[Block];
            for (int j = 0; j < d; j++)
            {
                double diag = sign * m[at + (Stride + 1) * j];
                for (int k = 0; k < j; k++) diag -= l[Stride * j + k] * l[Stride * j + k];
                if (!(diag > 1e-300) || double.IsInfinity(diag)) return false;
                double root = Math.Sqrt(diag);
                l[(Stride + 1) * j] = root;
                for (int i = j + 1; i < d; i++)
                {
                    double sum = sign * m[at + Stride * i + j];
                    for (int k = 0; k < j; k++) sum -= l[Stride * i + k] * l[Stride * j + k];
                    l[Stride * i + j] = sum / root;
                }
            }
            for (int j = 0; j < d; j++)
            {
                li[(Stride + 1) * j] = 1 / l[(Stride + 1) * j];
                for (int i = j + 1; i < d; i++)
                {
                    double sum = 0;
                    for (int k = j; k < i; k++) sum += l[Stride * i + k] * li[Stride * k + j];
                    li[Stride * i + j] = -sum / l[(Stride + 1) * i];
                }
            }
            for (int r = 0; r < d; r++)
                for (int c = r; c < d; c++)
                {
                    double sum = 0;
                    for (int k = c; k < d; k++) sum += li[Stride * k + r] * li[Stride * k + c];
                    m[at + Stride * r + c] = m[at + Stride * c + r] = sign * sum;
                }
            return true;
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
