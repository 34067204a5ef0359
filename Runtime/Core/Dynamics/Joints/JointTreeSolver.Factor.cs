using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The block LDL^T factorisation of the forest (each node's D^-1 and its block to the parent)
    /// and the rows it is built from: anchors, rotation locks, hinge and slider rows, the rod's
    /// length, across and tilt rows.
    /// </summary>
    internal sealed partial class JointTreeSolver
    {
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
    }
}
