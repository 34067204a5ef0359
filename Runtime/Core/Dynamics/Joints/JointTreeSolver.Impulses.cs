using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// One solve of the factored forest: the rigid impulses x = -A^-1 (J v + bias), the soft
    /// step's scaling of each row, one-sided rows released where the block would have them pull,
    /// and the impulses applied to the bodies.
    /// </summary>
    internal sealed partial class JointTreeSolver
    {
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
    }
}
