using System;
using System.Numerics;
using Fulcrum.Dynamics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A dynamic body that other Newton bodies are attached to as well. Each Newton body's step
    /// moves the rigid body as part of its own system (see the Attachments part), one soft body
    /// after another (block Gauss-Seidel). Seeing only the rigid body's own inertia, each dragged
    /// it to its own liking in turn: two bodies pinned to a 20 g hub, a 2.4 kg sphere landing on
    /// the ground and a 4.7 kg box still falling, took turns, the sphere's step slowing the hub
    /// to 0.7 m/s and the box's taking it back to its own 3.9 m/s fall. The box never felt the
    /// ground through the sphere, and the sphere, its pinned side driven into it every substep,
    /// gained energy until it inverted and blew apart (soft fuzz seed 82).
    /// <para>
    /// So a step sees each other Newton body's condensed response to the rigid body's move: the
    /// Schur complement of that body's system on the rigid body's six degrees of freedom,
    /// P = J^T H_AA J - C^T H_FF^-1 C (its inertia, strain and contact springs, its free vertices
    /// left to follow; the rigid body's own inertia and what others added taken out), kept from
    /// that body's last Newton step in this world step. The step's G gains q^T P q / 2: a body
    /// resting on the ground hands the others a stiff P, and the ground holds the hub through
    /// it; a body falling freely hands them its inertia (as a rigid whole where it is stiff, less
    /// where it is soft). After the step that body takes the move its P stands for: its vertices
    /// carried by the rigid body move with it (J q), its free vertices as its last Schur solve
    /// says they follow (-Z q), held to its trust region (a quarter of its shortest edge, as its
    /// own step is; a safeguard for a factor shifted near a singular direction), and each gains
    /// the move over h as velocity, so the momentum the step handed it is not lost. A body that
    /// has not begun this substep takes the move as velocity alone, which its own prediction then
    /// carries out: moved as well, it went twice as far (a stiff pair gained 15 J, and up to 4 kJ
    /// in a hard landing).
    /// </para>
    /// <para>
    /// The first body to step in a world step finds no P kept yet; nothing is carried from one
    /// world step to the next, so the world state is unchanged. Bodies solved by XPBD neither
    /// give nor take a response (their attachment projections move the other bodies' attached
    /// vertices with the rigid body: AttachmentSolver). A rigid body with axis locks is left out
    /// (its Schur rows are held). Measured on a 20 g and a 2 kg hub holding a Newton sphere and
    /// box dropped together (CouplingTests), the mechanical energy rose at most 791 J and 1180 J
    /// at E = 1e5 Pa and 24.5 J and 6.1 J at 5e6 Pa before, and not at all with this. Tried and
    /// dropped: the matrix alone with no move handed over (the momentum handed to the other body
    /// was lost: seed 82 still gained 259 J); the other bodies as rigid wholes with their momentum
    /// (stiff cases better, soft ones gained up to 78 J and two fuzz worlds newly failed); and a
    /// merge of the bodies' momenta before this scheme (2.3 kJ at 1e5 Pa).
    /// </para>
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
        // Per dynamic body of this body's last Newton step in this world step: its slot and
        // generation, and whether its condensed 6 x 6 (36 per body, row-major) is kept.
        int[] _condensedSlot = Array.Empty<int>();
        int[] _condensedGeneration = Array.Empty<int>();
        bool[] _condensedKept = Array.Empty<bool>();
        double[] _condensed = Array.Empty<double>();
        // Per dynamic body of this step: shared (other soft bodies attached, no axis locks), and
        // the sum of the other Newton bodies' kept responses (36) with whether there is one.
        bool[] _sharedBody = Array.Empty<bool>();
        double[] _partners = Array.Empty<double>();
        bool[] _hasPartners = Array.Empty<bool>();
        double _coupledInvH2;
        // The other Newton bodies whose responses this step added: the body, its index there,
        // and the index of the shared body here.
        SoftBody[] _partnerBody = Array.Empty<SoftBody>();
        int[] _partnerAt = Array.Empty<int>(), _partnerBeta = Array.Empty<int>();
        int _partnerCount;

        /// <summary>Forgets the condensed responses kept from the last world step (a world step starts).</summary>
        public void ForgetCondensed() => Array.Clear(_condensedKept, 0, _condensedKept.Length);

        void EnsureSharedStorage(int bodies)
        {
            if (_sharedBody.Length >= bodies) return;
            _condensedSlot = new int[bodies];
            _condensedGeneration = new int[bodies];
            _condensedKept = new bool[bodies];
            _condensed = new double[36 * bodies];
            _sharedBody = new bool[bodies];
            _partners = new double[36 * bodies];
            _hasPartners = new bool[bodies];
        }

        /// <summary>
        /// For each dynamic body of this step: whether it is shared, and the sum of the condensed
        /// responses the other Newton bodies kept for it.
        /// </summary>
        void GatherPartners(SoftBody body, RigidCoupling coupling)
        {
            EnsureSharedStorage(_bodyCount);
            Array.Clear(_partnerBody, 0, _partnerCount);
            _partnerCount = 0;
            BodyStorage b = body.World.Bodies;
            for (int beta = 0; beta < _bodyCount; beta++)
            {
                int slot = _bodies[beta];
                _hasPartners[beta] = false;
                _sharedBody[beta] = coupling.Shared(slot) && b.Locks[slot] == AxisLocks.None;
                if (!_sharedBody[beta]) continue;
                Array.Clear(_partners, 36 * beta, 36);
                for (int c = 0; c < coupling.CarrierCount; c++)
                {
                    SoftBody carrier = coupling.Carrier(c);
                    ImplicitNewtonSolver? other = carrier.NewtonSolver;
                    if (other == null || other == this || !other.Condensed(slot, b.Generation[slot], out int at)) continue;
                    for (int k = 0; k < 36; k++) _partners[36 * beta + k] += other._condensed[36 * at + k];
                    _hasPartners[beta] = true;
                    if (_partnerCount == _partnerBody.Length)
                    {
                        int grown = Math.Max(4, 2 * _partnerCount);
                        Array.Resize(ref _partnerBody, grown);
                        Array.Resize(ref _partnerAt, grown);
                        Array.Resize(ref _partnerBeta, grown);
                    }
                    _partnerBody[_partnerCount] = carrier;
                    _partnerAt[_partnerCount] = at;
                    _partnerBeta[_partnerCount++] = beta;
                }
            }
        }

        // Whether a dynamic body of this step is shared.
        bool HasShared()
        {
            for (int beta = 0; beta < _bodyCount; beta++)
                if (_sharedBody[beta]) return true;
            return false;
        }

        // Where this body kept its condensed response for the body in slot (of that generation).
        bool Condensed(int slot, int generation, out int at)
        {
            for (at = 0; at < _condensedKept.Length; at++)
                if (_condensedKept[at] && _condensedSlot[at] == slot && _condensedGeneration[at] == generation) return true;
            return false;
        }

        // Adds the others' condensed responses to the bodies' block of the Schur system (size x size).
        void AddPartners(int size, double invH2)
        {
            for (int beta = 0; beta < _bodyCount; beta++)
            {
                if (_sharedBody[beta]) _coupledInvH2 = invH2;
                if (!_hasPartners[beta]) continue;
                int o = 6 * beta;
                for (int a = 0; a < 6; a++)
                    for (int c = 0; c < 6; c++) _schur[(o + a) * size + o + c] += _partners[36 * beta + 6 * a + c];
            }
        }

        /// <summary>
        /// After the Schur complement is formed (before its factorisation): keeps this body's own
        /// condensed response for each shared body, the diagonal block less the rigid body's
        /// inertia and the others' responses added to it.
        /// </summary>
        void KeepCondensed(SoftBody body, int size)
        {
            BodyStorage b = body.World.Bodies;
            for (int beta = 0; beta < _bodyCount; beta++)
            {
                _condensedKept[beta] = false;
                if (!_sharedBody[beta]) continue;
                int o = 6 * beta;
                for (int a = 0; a < 6; a++)
                    for (int c = 0; c < 6; c++)
                    {
                        double own = _schur[(o + a) * size + o + c] - (_hasPartners[beta] ? _partners[36 * beta + 6 * a + c] : 0);
                        if (a < 3) own -= a == c ? _bodyMass[beta] * _coupledInvH2 : 0;
                        else if (c >= 3) own -= _bodyInertia[beta][a - 3, c - 3] * _coupledInvH2;
                        _condensed[36 * beta + 6 * a + c] = own;
                    }
                _condensedSlot[beta] = _bodies[beta];
                _condensedGeneration[beta] = b.Generation[_bodies[beta]];
                _condensedKept[beta] = true;
            }
            for (int beta = _bodyCount; beta < _condensedKept.Length; beta++) _condensedKept[beta] = false;
        }

        // The others' responses' part of G at fraction step of q: s^2 q^T P q / 2.
        double PartnerEnergy(double step)
        {
            double e = 0;
            for (int beta = 0; beta < _bodyCount; beta++)
            {
                if (!_hasPartners[beta]) continue;
                for (int a = 0; a < 6; a++)
                {
                    double row = 0;
                    for (int c = 0; c < 6; c++) row += _partners[36 * beta + 6 * a + c] * _q[6 * beta + c];
                    e += _q[6 * beta + a] * row;
                }
            }
            return 0.5 * step * step * e;
        }

        /// <summary>
        /// After this step moved the shared bodies by fraction <paramref name="step"/> of q: each
        /// other Newton body whose response the step counted takes the move that response stands
        /// for (see the class).
        /// </summary>
        void MovePartners(SoftBody self, float step, float h)
        {
            for (int p = 0; p < _partnerCount; p++)
            {
                int beta = _partnerBeta[p];
                Vector3 move = step * BodyMove(beta), turn = step * BodyTurn(beta);
                SoftBody other = _partnerBody[p];
                other.NewtonSolver!.Follow(other, _partnerAt[p], move, turn, _bodyCenter[beta], h, other.SubstepsBegun < self.SubstepsBegun);
            }
        }

        // This body follows a move (dc, dtheta) about centre c of its shared body at index at of
        // its last step: carried vertices with the body, free ones by -Z q scaled so that none
        // moves further than the trust region. A body that has not begun this substep yet
        // (ahead) takes the move as velocity alone, which its own prediction then carries out
        // (moved as well, it went twice as far).
        void Follow(SoftBody body, int at, Vector3 move, Vector3 turn, Vector3 center, float h, bool ahead)
        {
            Vector3[] x = body.X, v = body.V;
            float largest = 0;
            for (int i = 0; i < _n; i++)
                if (_carrier[i] < 0 && !_fixed[i]) largest = MathF.Max(largest, Response(i, at, move, turn).Length());
            float scale = largest > _reach ? _reach / largest : 1f;
            float keep = ahead && body.LinearDamping > 0 ? 1f / (1f + body.LinearDamping * h) : 1f;
            float invH = 1f / (h * keep);
            for (int i = 0; i < _n; i++)
            {
                int k = _carrier[i];
                if (k >= 0 ? _bodyOf[k] != at : _fixed[i]) continue;
                Vector3 d = k >= 0 ? move + Vector3.Cross(turn, x[i] - center) : scale * Response(i, at, move, turn);
                if (!ahead) x[i] += d;
                v[i] += d * invH;
            }
        }

        // How free vertex i follows the move (dc, dtheta) of shared body at: -Z q.
        Vector3 Response(int i, int at, Vector3 move, Vector3 turn)
        {
            int r = 3 * _order[i];
            double dx = 0, dy = 0, dz = 0;
            for (int j = 0; j < 6; j++)
            {
                double qj = j < 3 ? Component(move, j) : Component(turn, j - 3);
                if (qj == 0) continue;
                int column = (6 * at + j) * _dofs + r;
                dx -= _solved[column] * qj;
                dy -= _solved[column + 1] * qj;
                dz -= _solved[column + 2] * qj;
            }
            return new Vector3((float)dx, (float)dy, (float)dz);
        }
    }
}
