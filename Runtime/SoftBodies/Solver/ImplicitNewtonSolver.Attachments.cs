using System;
using System.Numerics;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Attachments inside the Newton step. An attached vertex is not a free unknown: it is the
    /// material point of its body, x_i = c + dc + R(dtheta) (a_i - c), so a dynamic body takes
    /// part in the step with its six degrees of freedom q = (dc, dtheta) and its inertia
    /// (m |dc|^2 + dtheta^T I dtheta) / (2 h^2) in G, as the rigid blocks of Augmented Vertex
    /// Block Descent (Giles, Diaz and Yuksel 2025) but in the global solve. Linearised, the
    /// attached vertices move by J_i q with J_i = [I, -[r_i]x], r_i = a_i - c; the system over
    /// (free vertices u, body q) is
    /// <code>
    /// [ H_FF       H_FA J              ] [u]   [r_F    ]
    /// [ J^T H_AF   J^T H_AA J + M / h^2] [q] = [J^T r_A]
    /// </code>
    /// solved by the Schur complement on q: the band factor of H_FF (attached rows held as
    /// Dirichlet rows) gives Z = H_FF^-1 H_FA J in 6 back-substitutions per body, then a dense
    /// 6k x 6k system for k bodies. The step is exact for the attachment (no projection after it
    /// strains the body) and the body's momentum change is what the step gave it.
    /// A vertex attached to a static or kinematic body is held at its anchor (a Dirichlet row).
    /// <para>
    /// Before, the step saw attached vertices as free and a projection after it moved them onto
    /// their anchors: a 0.16 kg box (E 2.7e9 Pa) pinned to a body spinning at 17 rad/s, its
    /// anchors moving 0.2 m per substep, was strained by each projection, thrown back by the next
    /// step, and inverted within a step (soft fuzz seed 229). With equal shares of the body's
    /// mass per attachment (as contacts have) the box no longer inverted at once, but the
    /// shares disagree with the body's rotation and the projection still stored up to 600 J per
    /// substep in the stiff box, growing until it diverged.
    /// </para>
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
        // Per vertex: held in place in this Newton step (pinned to the world, attached to a
        // static or kinematic body, or moved by a dynamic body's q).
        bool[] _fixed = Array.Empty<bool>();
        // Per vertex: the attachment that moves it with a dynamic body in this step, or -1.
        int[] _carrier = Array.Empty<int>();
        // Per attachment: its anchor now, and the index of its body in _bodies (Loose: it holds
        // nothing in this step; Held: its vertex is a Dirichlet row at the anchor).
        Vector3[] _anchor = Array.Empty<Vector3>();
        int[] _bodyOf = Array.Empty<int>();
        // The dynamic bodies in this step: slot, centre, mass, rotational inertia (free axes;
        // the identity on locked ones), locks; the coupling columns C = H_FA J (6 per body,
        // column j at j * _dofs), Z = H_FF^-1 C, the Schur system and q.
        int[] _bodies = Array.Empty<int>();
        Vector3[] _bodyCenter = Array.Empty<Vector3>();
        float[] _bodyMass = Array.Empty<float>();
        Mat3[] _bodyInertia = Array.Empty<Mat3>();
        int _bodyCount;
        double[] _columns = Array.Empty<double>(), _solved = Array.Empty<double>();
        double[] _schur = Array.Empty<double>(), _schurRhs = Array.Empty<double>(), _q = Array.Empty<double>();
        double[] _bodyRhs = Array.Empty<double>(), _schurSaved = Array.Empty<double>();
        int[] _vertexOfRow = Array.Empty<int>();
        const int Loose = -1, Held = -2;

        /// <summary>
        /// Finds what holds each vertex in this step, puts the attached vertices at their anchors
        /// and picks where the step starts (<see cref="StartAtAnchors"/>).
        /// </summary>
        void BeginAttachments(SoftBody body, Vector3[] x, Vector3[] y, double invH2, RigidCoupling coupling)
        {
            Attachment[] attachments = body.Attachments;
            if (_fixed.Length != _n)
            {
                _fixed = new bool[_n];
                _carrier = new int[_n];
                _vertexOfRow = new int[_n];
                for (int i = 0; i < _n; i++) _vertexOfRow[_order[i]] = i;
            }
            for (int i = 0; i < _n; i++)
            {
                _fixed[i] = body.W[i] == 0f;
                _carrier[i] = -1;
            }
            _bodyCount = 0;
            if (attachments.Length == 0) return;
            if (_anchor.Length != attachments.Length)
            {
                _anchor = new Vector3[attachments.Length];
                _bodyOf = new int[attachments.Length];
                _bodies = new int[attachments.Length];
                _bodyCenter = new Vector3[attachments.Length];
                _bodyMass = new float[attachments.Length];
                _bodyInertia = new Mat3[attachments.Length];
            }
            BodyStorage b = body.World.Bodies;
            for (int k = 0; k < attachments.Length; k++)
            {
                _bodyOf[k] = Loose;
                int i = attachments[k].Vertex;
                // A vertex pinned to the world, or already held by an earlier attachment, stays so.
                if (_fixed[i] || !AttachmentSolver.Anchor(b, attachments[k], out _anchor[k])) continue;
                x[i] = _anchor[k];
                _fixed[i] = true;
                _bodyOf[k] = Held;
                int slot = attachments[k].BodySlot;
                if (b.Type[slot] != BodyType.Dynamic || (b.Locks[slot] & AxisLocks.All) == AxisLocks.All) continue;
                int index = 0;
                while (index < _bodyCount && _bodies[index] != slot) index++;
                if (index == _bodyCount)
                {
                    _bodies[index] = slot;
                    _bodyCenter[index] = b.Center[slot];
                    _bodyMass[index] = 1f / b.InverseMass[slot];
                    // P I^-1 P is zero on locked rotation axes: the identity there makes it
                    // invertible, and those axes are held in the Schur system.
                    Vector3 locked = Vector3.One - AxisLockMath.AngularMask(b.Locks[slot]);
                    if (!(b.InverseInertiaWorld[slot] + Mat3.Diagonal(locked)).TryInvert(out _bodyInertia[index]) || !_bodyInertia[index].IsFinite) continue;
                    _bodyCount++;
                }
                _bodyOf[k] = index;
                _carrier[i] = k;
            }
            EnsureBodyStorage();
            GatherPartners(body, coupling);
            StartAtAnchors(body, x, y, invH2);
        }

        void EnsureBodyStorage()
        {
            int size = 6 * _bodyCount;
            if (_columns.Length < size * _dofs)
            {
                _columns = new double[size * _dofs];
                _solved = new double[size * _dofs];
            }
            if (_schurRhs.Length < size)
            {
                _schur = new double[size * size];
                _schurRhs = new double[size];
                _bodyRhs = new double[size];
                _q = new double[size];
            }
        }

        /// <summary>
        /// Where the step starts: the attached vertices at their anchors, and the others either
        /// where they are or carried by the rigid motion that best takes the attached vertices
        /// there (the shape-matching fit of Mueller et al. 2005), whichever has the lower G. Only
        /// the start of the iteration changes, not its minimum; but a stiff body whipped by its
        /// attachment has its lowest energy near that rigid motion, many trust-region steps
        /// away from where its inertia alone would take it (the soft fuzz seed 229 box stayed
        /// stretched by 0.2 m after each substep's two Newton steps).
        /// </summary>
        void StartAtAnchors(SoftBody body, Vector3[] x, Vector3[] y, double invH2)
        {
            Attachment[] attachments = body.Attachments;
            Vector3 from = Vector3.Zero, to = Vector3.Zero;
            int count = 0;
            for (int k = 0; k < attachments.Length; k++)
            {
                if (!Holds(k)) continue;
                from += body.XPrev[attachments[k].Vertex];
                to += _anchor[k];
                count++;
            }
            if (count == 0) return;
            from /= count;
            to /= count;
            Mat3 covariance = default;
            for (int k = 0; k < attachments.Length; k++)
                if (Holds(k)) covariance += Mat3.Outer(_anchor[k] - to, body.XPrev[attachments[k].Vertex] - from);
            Quaternion turn = BestRotation(covariance);
            double stay = Energy(body, x, y, invH2);
            Array.Copy(x, _trial, _n);
            for (int i = 0; i < _n; i++)
                if (!_fixed[i]) _trial[i] = to + Vector3.Transform(body.XPrev[i] - from, turn);
            if (Energy(body, _trial, y, invH2) < stay) Array.Copy(_trial, x, _n);
        }

        // Whether attachment k put its vertex at its anchor in this step.
        bool Holds(int k) => _bodyOf[k] != Loose;

        /// <summary>
        /// The rotation closest to the covariance A = sum (q - q0)(p - p0)^T (the rotational
        /// part of its polar decomposition), by the iteration of Mueller, Bender, Chentanez and
        /// Macklin 2016, "A Robust Method to Extract the Rotational Part of Deformations", from
        /// the identity: with fewer than three independent directions it is the smallest
        /// rotation that fits.
        /// </summary>
        static Quaternion BestRotation(in Mat3 a)
        {
            Quaternion q = Quaternion.Identity;
            float scale = MathF.Sqrt(a.FrobeniusSquared);
            if (!(scale > 0f) || !float.IsFinite(scale)) return q;
            for (int iteration = 0; iteration < 30; iteration++)
            {
                Mat3 r = Mat3.FromQuaternion(q);
                Vector3 omega = (Vector3.Cross(r.C0, a.C0) + Vector3.Cross(r.C1, a.C1) + Vector3.Cross(r.C2, a.C2))
                    / (MathF.Abs(Vector3.Dot(r.C0, a.C0) + Vector3.Dot(r.C1, a.C1) + Vector3.Dot(r.C2, a.C2)) + 1e-9f * scale);
                float angle = omega.Length();
                if (angle < 1e-7f) break;
                q = Quaternion.Normalize(Quaternion.CreateFromAxisAngle(omega / angle, angle) * q);
            }
            return q;
        }

        // The assembled (lower band) matrix entry at (row, col), either triangle; 0 outside the band.
        double Get(int row, int col)
        {
            if (row < col) (row, col) = (col, row);
            return row - col > _band ? 0 : At(row, col);
        }

        /// <summary>
        /// Before the Dirichlet rows are set: the coupling columns C = H_FA J, the bodies' block
        /// J^T H_AA J + M / h^2 and right-hand side J^T r_A, from the assembled matrix.
        /// </summary>
        void CoupleBodies(SoftBody body, double invH2)
        {
            int size = 6 * _bodyCount;
            Array.Clear(_columns, 0, size * _dofs);
            Array.Clear(_schur, 0, size * size);
            Array.Clear(_schurRhs, 0, size);
            Attachment[] attachments = body.Attachments;
            Span<double> row6 = stackalloc double[6];
            for (int i = 0; i < _n; i++)
            {
                int k = _carrier[i];
                if (k < 0) continue;
                int beta = _bodyOf[k];
                // In doubles throughout: for a stiff body the Schur complement is the small
                // difference of large stiffness terms (the elastic energy does not change under a
                // rigid motion of the body and what it carries), and float rounding there turned
                // the step away from descent (E 1e9 Pa).
                Vector3 lever = _anchor[k] - _bodyCenter[beta];
                double rx = lever.X, ry = lever.Y, rz = lever.Z;
                int ri = 3 * _order[i];
                double fx = _rhs[ri], fy = _rhs[ri + 1], fz = _rhs[ri + 2];
                _schurRhs[6 * beta] += fx;
                _schurRhs[6 * beta + 1] += fy;
                _schurRhs[6 * beta + 2] += fz;
                _schurRhs[6 * beta + 3] += ry * fz - rz * fy;
                _schurRhs[6 * beta + 4] += rz * fx - rx * fz;
                _schurRhs[6 * beta + 5] += rx * fy - ry * fx;
                int first = Math.Max(0, ri - _band), last = Math.Min(_dofs - 1, ri + 2 + _band);
                for (int row = first; row <= last; row++)
                {
                    int v = _vertexOfRow[row / 3];
                    if (_fixed[v] && _carrier[v] < 0) continue; // held: no motion to couple
                    // (row of H) J_i = [h, r x h] with h the row's three entries in i's columns.
                    double h0 = Get(row, ri), h1 = Get(row, ri + 1), h2 = Get(row, ri + 2);
                    if (h0 == 0 && h1 == 0 && h2 == 0) continue;
                    row6[0] = h0; row6[1] = h1; row6[2] = h2;
                    row6[3] = ry * h2 - rz * h1;
                    row6[4] = rz * h0 - rx * h2;
                    row6[5] = rx * h1 - ry * h0;
                    if (_carrier[v] < 0)
                    {
                        for (int j = 0; j < 6; j++) _columns[(6 * beta + j) * _dofs + row] += row6[j];
                        continue;
                    }
                    // A row of another carried vertex: J_v^T = [I; [r_v]x] takes it into the bodies' block.
                    int kv = _carrier[v], gamma = _bodyOf[kv];
                    int component = row - 3 * _order[v];
                    Vector3 rv = _anchor[kv] - _bodyCenter[gamma];
                    // [r_v]x e_c: the column of the skew matrix for this component.
                    double lx = component == 0 ? 0 : component == 1 ? -rv.Z : rv.Y;
                    double ly = component == 0 ? rv.Z : component == 1 ? 0 : -rv.X;
                    double lz = component == 0 ? -rv.Y : component == 1 ? rv.X : 0;
                    for (int j = 0; j < 6; j++)
                    {
                        double value = row6[j];
                        _schur[(6 * gamma + component) * size + 6 * beta + j] += value;
                        _schur[(6 * gamma + 3) * size + 6 * beta + j] += lx * value;
                        _schur[(6 * gamma + 4) * size + 6 * beta + j] += ly * value;
                        _schur[(6 * gamma + 5) * size + 6 * beta + j] += lz * value;
                    }
                }
            }
            BodyStorage b = body.World.Bodies;
            for (int beta = 0; beta < _bodyCount; beta++)
            {
                int o = 6 * beta;
                for (int c = 0; c < 3; c++) _schur[(o + c) * size + o + c] += _bodyMass[beta] * invH2;
                for (int a = 0; a < 3; a++)
                    for (int c = 0; c < 3; c++)
                        _schur[(o + 3 + a) * size + o + 3 + c] += _bodyInertia[beta][a, c] * invH2;
                // Locked axes: the body does not move along them.
                AxisLocks locks = b.Locks[_bodies[beta]];
                for (int d = 0; d < 6; d++)
                {
                    if (((int)locks & (1 << d)) == 0) continue;
                    for (int j = 0; j < size; j++) _schur[(o + d) * size + j] = _schur[j * size + o + d] = 0;
                    _schur[(o + d) * size + o + d] = 1;
                    _schurRhs[o + d] = 0;
                    Array.Clear(_columns, (o + d) * _dofs, _dofs);
                }
            }
            AddPartners(size, invH2);
            Array.Copy(_schurRhs, _bodyRhs, size);
        }

        /// <summary>
        /// After the band factor and the free solve u0 = H_FF^-1 r_F (in _rhs): the bodies' q
        /// from the Schur complement, and the free step u = u0 - Z q in _rhs. False when the
        /// Schur system is singular (no step).
        /// </summary>
        bool SolveBodies(SoftBody body)
        {
            int size = 6 * _bodyCount;
            Array.Copy(_columns, _solved, size * _dofs);
            for (int j = 0; j < size; j++) Solve(_solved, j * _dofs);
            for (int a = 0; a < size; a++)
            {
                double rhs = 0;
                for (int row = 0; row < _dofs; row++) rhs += _columns[a * _dofs + row] * _rhs[row];
                _schurRhs[a] -= rhs;
                for (int c = 0; c < size; c++)
                {
                    double s = 0;
                    for (int row = 0; row < _dofs; row++) s += _columns[a * _dofs + row] * _solved[c * _dofs + row];
                    _schur[a * size + c] -= s;
                }
            }
            if (HasShared()) KeepCondensed(body, size);
            if (!ShiftedCholesky(size)) return false;
            for (int c = 0; c < size; c++)
            {
                double qc = _q[c];
                if (qc == 0) continue;
                for (int row = 0; row < _dofs; row++) _rhs[row] -= _solved[c * _dofs + row] * qc;
            }
            return true;
        }

        /// <summary>
        /// Solves S q = b by Cholesky. S is the Schur complement of a Hessian that is indefinite
        /// where the body is pre-stressed (a stiff box whipped round on a 3 m lever: along the
        /// linearised turn of the body and what it carries, the tension's geometric stiffness
        /// can outweigh the inertia), and Gaussian elimination then returned a q that was no
        /// descent direction, so the step was refused; a non-positive pivot adds a diagonal
        /// shift instead (1e-8 of the largest diagonal, x4 per retry, as the band factor does),
        /// which keeps the step a descent direction. False when S is still not factored after
        /// <see cref="MaxShifts"/> shifts (a non-finite entry).
        /// </summary>
        bool ShiftedCholesky(int n)
        {
            if (_schurSaved.Length < n * n) _schurSaved = new double[n * n];
            Array.Copy(_schur, _schurSaved, n * n);
            double largest = 0;
            for (int i = 0; i < n; i++) largest = Math.Max(largest, _schur[i * n + i]);
            if (!(largest > 0) || double.IsInfinity(largest)) return false;
            double shift = 0;
            for (int tries = 0; !DenseCholesky.Factor(_schur, n); tries++)
            {
                if (tries == MaxShifts) return false;
                shift = shift == 0 ? 1e-8 * largest : 4 * shift;
                Array.Copy(_schurSaved, _schur, n * n);
                for (int i = 0; i < n; i++) _schur[i * n + i] += shift;
            }
            Array.Copy(_schurRhs, _q, n);
            DenseCholesky.Solve(_schur, n, _q);
            for (int i = 0; i < n; i++) if (!double.IsFinite(_q[i])) return false;
            return true;
        }

        /// <summary>The bodies' part of the slope of G along the step: -(J^T r_A) . q.</summary>
        double BodySlope()
        {
            double s = 0;
            for (int a = 0; a < 6 * _bodyCount; a++) s -= _bodyRhs[a] * _q[a];
            return s;
        }

        /// <summary>Moves the carried vertices by fraction <paramref name="step"/> of q: x_i = c + s dc + R(s dtheta)(x_i - c).</summary>
        void CarryTrial(Vector3[] x, float step)
        {
            for (int i = 0; i < _n; i++)
            {
                int k = _carrier[i];
                if (k < 0) continue;
                int beta = _bodyOf[k];
                Quaternion turn = Rotation.FromRotationVector(step * BodyTurn(beta));
                _trial[i] = _bodyCenter[beta] + step * BodyMove(beta) + Vector3.Transform(x[i] - _bodyCenter[beta], turn);
            }
        }

        /// <summary>The bodies' inertia at fraction <paramref name="step"/> of q: s^2 (m |dc|^2 + dtheta^T I dtheta) / (2 h^2).</summary>
        double BodyEnergy(double step, double invH2)
        {
            double e = 0;
            for (int beta = 0; beta < _bodyCount; beta++)
            {
                Vector3 move = BodyMove(beta), turn = BodyTurn(beta);
                e += _bodyMass[beta] * move.LengthSquared() + Vector3.Dot(turn, _bodyInertia[beta] * turn);
            }
            return 0.5 * invH2 * step * step * e + PartnerEnergy(step);
        }

        /// <summary>The largest move of a carried vertex at the full step, m.</summary>
        double LargestCarried()
        {
            double largest = 0;
            for (int i = 0; i < _n; i++)
            {
                int k = _carrier[i];
                if (k < 0) continue;
                int beta = _bodyOf[k];
                Vector3 move = BodyMove(beta) + Vector3.Cross(BodyTurn(beta), _anchor[k] - _bodyCenter[beta]);
                largest = Math.Max(largest, move.Length());
            }
            return largest;
        }

        /// <summary>Gives each body the step's fraction <paramref name="step"/> of q: position impulse m s dc and its moment I s dtheta.</summary>
        void PushCarriers(float step, float h, RigidCoupling coupling)
        {
            for (int beta = 0; beta < _bodyCount; beta++)
                coupling.PushSum(_bodies[beta], _bodyMass[beta] * step * BodyMove(beta), _bodyInertia[beta] * (step * BodyTurn(beta)), h);
        }

        Vector3 BodyMove(int beta) => new Vector3((float)_q[6 * beta], (float)_q[6 * beta + 1], (float)_q[6 * beta + 2]);

        Vector3 BodyTurn(int beta) => new Vector3((float)_q[6 * beta + 3], (float)_q[6 * beta + 4], (float)_q[6 * beta + 5]);
    }
}
