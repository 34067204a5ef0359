using System;
using System.Numerics;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Holds attached vertices at their anchors on rigid bodies: a zero-compliance XPBD
    /// distance-to-point constraint shared between the vertex's inverse mass and the body's
    /// generalised inverse mass at the anchor, so the body carries what hangs from it.
    /// A destroyed body releases its vertices.
    /// </summary>
    internal static class AttachmentSolver
    {
        /// <summary>
        /// Projects the attachments, each run of consecutive attachments to one dynamic body as
        /// one block (a pin's attachments are consecutive): the body's move q = (dc, dtheta) and
        /// the vertices' moves that put every vertex of the run on its anchor, in the mass metric,
        /// from (M_b + sum m_k J_k^T J_k) q = sum m_k J_k^T d_k with J_k = [I, -[r_k]x] (the
        /// anchor's move per body move), d_k the vertex's offset from its anchor and m_k its mass;
        /// each vertex then moves by -(d_k - J_k q) and the body takes the position impulses
        /// m_k (d_k - J_k q). That is the projection of the body and its attached vertices as one
        /// rigid whole. Projected one attachment at a time (Gauss-Seidel), a body lighter than the
        /// vertices it holds was swung by each projection about its lever, moving every other
        /// anchor as far: a 1.2 kg cloth pinned along an edge to a 0.5 kg body 1.5 m away, at
        /// rest in zero gravity, spun the body up to 200 rad/s within a second (more sweeps per
        /// iteration made it worse). Static and kinematic bodies hold their vertices at the anchors.
        /// </summary>
        public static void Solve(World world, SoftBody body, Vector3[] x, float[] w, float h, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            Attachment[] attachments = body.Attachments;
            for (int start = 0; start < attachments.Length;)
            {
                int slot = attachments[start].BodySlot, generation = attachments[start].BodyGeneration;
                int end = start + 1;
                while (end < attachments.Length && attachments[end].BodySlot == slot && attachments[end].BodyGeneration == generation) end++;
                if (b.Generation[slot] == generation && b.ActiveIndex[slot] >= 0)
                {
                    if (b.Type[slot] == BodyType.Dynamic) SolveRun(b, body, start, end, x, w, h, coupling);
                    else Hold(b, attachments, start, end, x, w);
                }
                start = end;
            }
        }

        /// <summary>
        /// The attachments one at a time, each along its vertex's offset from the anchor with the
        /// body's inverse mass along that line: what a Newton body takes after its step and its
        /// contact pass. Its step moves the attached vertices with their bodies exactly (the
        /// bodies are in its system), so this only hands back what the contact pass moved; solved
        /// as a block instead, a 100 kg body holding a nu = 0.4999 sphere on a 1.8 m lever, lying
        /// on the ground with the sphere pressed into it, was still sliding at 0.42 m/s after 3 s
        /// (0.09 one at a time).
        /// </summary>
        public static void SolveEach(World world, Attachment[] attachments, Vector3[] x, float[] w, float h, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            for (int k = 0; k < attachments.Length; k++)
            {
                ref Attachment a = ref attachments[k];
                int slot = a.BodySlot;
                float wv = w[a.Vertex];
                if (wv == 0f || !Anchor(b, a, out Vector3 anchor)) continue;
                Vector3 d = x[a.Vertex] - anchor;
                float length = d.Length();
                if (length < 1e-9f) continue;
                Vector3 n = d / length;
                float dl = length / (wv + coupling.InverseMassAt(slot, anchor, n));
                x[a.Vertex] -= wv * dl * n;
                coupling.Push(slot, anchor, dl * n, h);
            }
        }

        // Vertices on a static or kinematic body: at their anchors.
        static void Hold(BodyStorage b, Attachment[] attachments, int start, int end, Vector3[] x, float[] w)
        {
            for (int k = start; k < end; k++)
                if (w[attachments[k].Vertex] != 0f && Anchor(b, attachments[k], out Vector3 anchor)) x[attachments[k].Vertex] = anchor;
        }

        // One dynamic body's run of attachments as one block (see Solve). The attached vertices
        // of other soft bodies on the same rigid body are part of the rigid whole too (see
        // SolveShared).
        static void SolveRun(BodyStorage b, SoftBody body, int start, int end, Vector3[] x, float[] w, float h, RigidCoupling coupling)
        {
            Attachment[] attachments = body.Attachments;
            Span<double> a = stackalloc double[36];
            Span<double> q = stackalloc double[6];
            a.Clear();
            q.Clear();
            int slot = attachments[start].BodySlot;
            Vector3 center = b.Center[slot];
            bool any = false;
            for (int k = start; k < end; k++)
            {
                int i = attachments[k].Vertex;
                if (w[i] == 0f) continue;
                Anchor(b, attachments[k], out Vector3 anchor);
                AddVertex(a, q, 1.0 / w[i], anchor - center, x[i] - anchor);
                any = true;
            }
            if (!any) return;
            bool shared = coupling.Shared(slot);
            if (shared) SharedVertices(b, body, slot, center, coupling, a, q, h, move: false);
            if (!AddBody(b, slot, a, out _, out _)) return;
            AxisLocks locks = b.Locks[slot];
            for (int dof = 0; dof < 6; dof++) if (((int)locks & (1 << dof)) != 0) q[dof] = 0;
            if (!DenseCholesky.Factor(a, 6)) return;
            DenseCholesky.Solve(a, 6, q);
            Vector3 move = new Vector3((float)q[0], (float)q[1], (float)q[2]), turn = new Vector3((float)q[3], (float)q[4], (float)q[5]);
            Vector3 linear = Vector3.Zero, angular = Vector3.Zero;
            for (int k = start; k < end; k++)
            {
                int i = attachments[k].Vertex;
                if (w[i] == 0f) continue;
                Anchor(b, attachments[k], out Vector3 anchor);
                Vector3 r = anchor - center;
                Vector3 gap = x[i] - anchor - (move + Vector3.Cross(turn, r));
                Vector3 impulse = gap / w[i];
                x[i] -= gap;
                linear += impulse;
                angular += Vector3.Cross(r, impulse);
            }
            if (shared)
            {
                q[0] = move.X; q[1] = move.Y; q[2] = move.Z; q[3] = turn.X; q[4] = turn.Y; q[5] = turn.Z;
                Span<double> sums = stackalloc double[6];
                sums.Clear();
                SharedVertices(b, body, slot, center, coupling, sums, q, h, move: true);
                linear += new Vector3((float)sums[0], (float)sums[1], (float)sums[2]);
                angular += new Vector3((float)sums[3], (float)sums[4], (float)sums[5]);
            }
            coupling.PushSum(slot, linear, angular, h);
        }

        /// <summary>
        /// Moves the dynamic body in <paramref name="slot"/> and every vertex attached to it (this
        /// soft body's, and other soft bodies' when they share it) as one rigid whole, so that the
        /// whole's point at <paramref name="point"/> moves <paramref name="move"/> along
        /// <paramref name="n"/> (unit): the least-inertia move q = A^-1 J^T n P, with A the
        /// whole's mass matrix (as <see cref="Solve"/>'s block: the body's mass and inertia plus
        /// m_k J_k^T J_k of each attached vertex) and P = move / (n . J A^-1 J^T n), the impulse
        /// along n that the point takes. The body takes its share (M dc, I dtheta) as a position
        /// impulse, so its velocity changes by its move over h; the attached vertices move with
        /// their anchors (a body that has not begun the substep takes it as velocity, as in
        /// <see cref="SharedVertices"/>). Pushing the body alone, a 20 g body holding two heavy
        /// Newton bodies was pushed far, pulled back by them in their attachment passes, and the
        /// three gained 1.4e4 J (soft fuzz seed 82).
        /// </summary>
        public static void MoveWhole(World world, SoftBody body, int slot, Vector3 point, Vector3 n, float move, float h, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            Span<double> a = stackalloc double[36];
            Span<double> q = stackalloc double[6];
            Span<double> unused = stackalloc double[6];
            a.Clear();
            unused.Clear();
            Vector3 center = b.Center[slot];
            Attachment[] attachments = body.Attachments;
            Vector3[] x = body.X;
            float[] w = body.W;
            int generation = b.Generation[slot];
            for (int k = 0; k < attachments.Length; k++)
            {
                int i = attachments[k].Vertex;
                if (attachments[k].BodySlot != slot || attachments[k].BodyGeneration != generation || w[i] == 0f) continue;
                Anchor(b, attachments[k], out Vector3 anchor);
                AddBlock(a, 1.0 / w[i], anchor - center);
            }
            bool shared = coupling.Shared(slot);
            if (shared) SharedVertices(b, body, slot, center, coupling, a, unused, h, move: false);
            if (!AddBody(b, slot, a, out float mass, out Mat3 inertia) || !DenseCholesky.Factor(a, 6)) return;
            Vector3 r = point - center, rn = Vector3.Cross(r, n);
            q[0] = n.X; q[1] = n.Y; q[2] = n.Z; q[3] = rn.X; q[4] = rn.Y; q[5] = rn.Z;
            AxisLocks locks = b.Locks[slot];
            for (int dof = 0; dof < 6; dof++) if (((int)locks & (1 << dof)) != 0) q[dof] = 0;
            DenseCholesky.Solve(a, 6, q);
            Vector3 dc = new Vector3((float)q[0], (float)q[1], (float)q[2]), turn = new Vector3((float)q[3], (float)q[4], (float)q[5]);
            float along = Vector3.Dot(dc + Vector3.Cross(turn, r), n);
            if (!(along > 0f)) return;
            float scale = move / along;
            dc *= scale;
            turn *= scale;
            for (int k = 0; k < attachments.Length; k++)
            {
                int i = attachments[k].Vertex;
                if (attachments[k].BodySlot != slot || attachments[k].BodyGeneration != generation || w[i] == 0f) continue;
                Anchor(b, attachments[k], out Vector3 anchor);
                x[i] += dc + Vector3.Cross(turn, anchor - center);
            }
            if (shared)
            {
                q[0] = dc.X; q[1] = dc.Y; q[2] = dc.Z; q[3] = turn.X; q[4] = turn.Y; q[5] = turn.Z;
                unused.Clear();
                SharedVertices(b, body, slot, center, coupling, unused, q, h, move: true);
            }
            coupling.PushSum(slot, mass * dc, inertia * turn, h);
        }

        // The body's own inertia into a block: its mass on the translation, I (world) on the
        // rotation; locked axes are held (their rows the identity, no move). False when the
        // inertia cannot be inverted.
        static bool AddBody(BodyStorage b, int slot, Span<double> a, out float mass, out Mat3 inertia)
        {
            mass = 1f / b.InverseMass[slot];
            Vector3 locked = Vector3.One - AxisLockMath.AngularMask(b.Locks[slot]);
            if (!(b.InverseInertiaWorld[slot] + Mat3.Diagonal(locked)).TryInvert(out inertia)) return false;
            for (int c = 0; c < 3; c++) a[7 * c] += mass;
            for (int row = 0; row < 3; row++)
                for (int col = 0; col < 3; col++) a[6 * (3 + row) + 3 + col] += inertia[row, col];
            AxisLocks locks = b.Locks[slot];
            for (int dof = 0; dof < 6; dof++)
            {
                if (((int)locks & (1 << dof)) == 0) continue;
                for (int j = 0; j < 6; j++) a[6 * dof + j] = a[6 * j + dof] = 0;
                a[7 * dof] = 1;
            }
            return true;
        }

        /// <summary>
        /// The attached vertices of the other soft bodies on the rigid body in
        /// <paramref name="slot"/>: they are part of the rigid whole the block moves, so they go
        /// into its mass matrix and right-hand side (<paramref name="move"/> false: a and q), and
        /// after the solve onto their moved anchors, their velocity changed by the move over h and
        /// their impulses summed into <paramref name="a"/>'s first six entries (true; q holds the
        /// solved move). Left out, each soft body's projection took a light rigid body to its own
        /// vertices in turn (a 0.68 kg body holding 199 kg and 351 kg XPBD bodies was flung to
        /// 440 m/s within three steps, soft fuzz seed 10862), as the Newton step did before it saw
        /// the other bodies (ImplicitNewtonSolver.SharedBodies).
        /// </summary>
        static void SharedVertices(BodyStorage b, SoftBody self, int slot, Vector3 center, RigidCoupling coupling, Span<double> a, Span<double> q, float h, bool move)
        {
            Vector3 dc = new Vector3((float)q[0], (float)q[1], (float)q[2]), dtheta = new Vector3((float)q[3], (float)q[4], (float)q[5]);
            for (int c = 0; c < coupling.CarrierCount; c++)
            {
                SoftBody other = coupling.Carrier(c);
                if (other == self) continue;
                Attachment[] attachments = other.Attachments;
                Vector3[] x = other.X, v = other.V;
                float[] w = other.W;
                // A body that has not begun this substep yet is still at its last substep's end:
                // it is taken where its own prediction puts it (x + h (v + g h) keep), and handed
                // the correction as velocity alone, which its prediction then carries out (moved
                // as well, it went twice as far and gained energy). One that has stepped is moved
                // and its velocity changed by the move over h, as its own pass would have.
                bool ahead = other.SubstepsBegun < self.SubstepsBegun;
                float keep = other.LinearDamping > 0 ? 1f / (1f + other.LinearDamping * h) : 1f;
                Vector3 gravity = other.GravityStep(h);
                float invH = ahead ? 1f / (h * keep) : 1f / h;
                for (int k = 0; k < attachments.Length; k++)
                {
                    int i = attachments[k].Vertex;
                    if (attachments[k].BodySlot != slot || w[i] == 0f || !Anchor(b, attachments[k], out Vector3 anchor)) continue;
                    Vector3 at = ahead ? x[i] + (v[i] + gravity) * (keep * h) : x[i];
                    Vector3 r = anchor - center, d = at - anchor;
                    if (!move)
                    {
                        AddVertex(a, q, 1.0 / w[i], r, d);
                        continue;
                    }
                    Vector3 gap = d - (dc + Vector3.Cross(dtheta, r));
                    Vector3 impulse = gap / w[i], rp = Vector3.Cross(r, impulse);
                    if (!ahead) x[i] -= gap;
                    v[i] -= gap * invH;
                    a[0] += impulse.X; a[1] += impulse.Y; a[2] += impulse.Z;
                    a[3] += rp.X; a[4] += rp.Y; a[5] += rp.Z;
                }
            }
        }

        // One vertex of the block: a += m J^T J, q += m J^T d (J^T d = (d, r x d)).
        static void AddVertex(Span<double> a, Span<double> q, double m, Vector3 r, Vector3 d)
        {
            AddBlock(a, m, r);
            Vector3 rd = Vector3.Cross(r, d);
            q[0] += m * d.X; q[1] += m * d.Y; q[2] += m * d.Z;
            q[3] += m * rd.X; q[4] += m * rd.Y; q[5] += m * rd.Z;
        }

        // a += m J^T J for J = [I, -[r]x] (row-major 6 x 6).
        static void AddBlock(Span<double> a, double m, Vector3 r)
        {
            double x = r.X, y = r.Y, z = r.Z;
            // Upper left: I.
            a[0] += m; a[7] += m; a[14] += m;
            // Upper right: -[r]x; lower left: [r]x (its transpose).
            // [r]x = [[0, -z, y], [z, 0, -x], [-y, x, 0]].
            a[4] += m * z; a[5] -= m * y;
            a[9] -= m * z; a[11] += m * x;
            a[15] += m * y; a[16] -= m * x;
            a[19] -= m * z; a[20] += m * y;
            a[24] += m * z; a[26] -= m * x;
            a[30] -= m * y; a[31] += m * x;
            // Lower right: -[r]x^2 = |r|^2 I - r r^T.
            double rr = x * x + y * y + z * z;
            a[21] += m * (rr - x * x); a[22] -= m * x * y; a[23] -= m * x * z;
            a[27] -= m * y * x; a[28] += m * (rr - y * y); a[29] -= m * y * z;
            a[33] -= m * z * x; a[34] -= m * z * y; a[35] += m * (rr - z * z);
        }


        /// <summary>Where attachment <paramref name="a"/>'s body holds its vertex now; false when the body was destroyed.</summary>
        public static bool Anchor(BodyStorage b, in Attachment a, out Vector3 anchor)
        {
            int slot = a.BodySlot;
            if (b.Generation[slot] != a.BodyGeneration || b.ActiveIndex[slot] < 0)
            {
                anchor = default;
                return false;
            }
            anchor = b.Position[slot] + Vector3.Transform(a.LocalAnchor, b.Rotation[slot]);
            return true;
        }

        /// <summary>
        /// After the damping pass: an attached vertex moves with its body, so the velocity the
        /// pass gave it is shared with the body by the impulse J that makes the two move
        /// together, J = (w I + K)^-1 (v - u) (w the vertex's inverse mass, K the body's
        /// <see cref="RigidCoupling.PointInverseMass"/> at the vertex, v the vertex's velocity and
        /// u the body point's): the vertex keeps v - w J, the body gains J, and the pair's
        /// momentum is kept and its energy only lost. Left on the vertex alone, the attachment
        /// dragged the body back to it every substep and a hanging box jittered; handed over
        /// whole (J = m (v - u), right only for a body much heavier than the vertex at that
        /// point), it spun a 33 g body with a cloth pinned 5 m from its centre to NaN within a
        /// step: there the body is lighter than the vertex, and each hand-over overshot.
        /// </summary>
        public static void HandDampingToBodies(World world, Attachment[] attachments, Vector3[] x, Vector3[] v, float[] w, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            for (int k = 0; k < attachments.Length; k++)
            {
                ref Attachment a = ref attachments[k];
                int slot = a.BodySlot;
                if (b.Generation[slot] != a.BodyGeneration || b.ActiveIndex[slot] < 0 || b.Type[slot] != BodyType.Dynamic) continue;
                int i = a.Vertex;
                if (w[i] == 0f) continue;
                Mat3 k3 = coupling.PointInverseMass(slot, x[i]) + Mat3.Diagonal(new Vector3(w[i]));
                if (!k3.TryInvert(out Mat3 inverse)) continue;
                Vector3 impulse = inverse * (v[i] - coupling.PointVelocity(slot, x[i]));
                coupling.Kick(slot, x[i], impulse);
                v[i] -= w[i] * impulse;
            }
        }

        /// <summary>The largest mass of a live dynamic body with vertices attached, kg (0 for none).</summary>
        public static float HeaviestBody(World world, Attachment[] attachments)
        {
            BodyStorage b = world.Bodies;
            float heaviest = 0;
            for (int k = 0; k < attachments.Length; k++)
            {
                int slot = attachments[k].BodySlot;
                if (b.Generation[slot] == attachments[k].BodyGeneration && b.ActiveIndex[slot] >= 0 && b.Type[slot] == BodyType.Dynamic)
                    heaviest = System.MathF.Max(heaviest, b.Mass[slot]);
            }
            return heaviest;
        }

        /// <summary>
        /// Tracks every live body that has vertices of <paramref name="body"/> attached, and notes
        /// that the body carries them (<see cref="RigidCoupling.Carry"/>).
        /// </summary>
        public static void Track(World world, SoftBody body, RigidCoupling coupling)
        {
            BodyStorage b = world.Bodies;
            Attachment[] attachments = body.Attachments;
            for (int k = 0; k < attachments.Length; k++)
            {
                int slot = attachments[k].BodySlot;
                if (b.Generation[slot] != attachments[k].BodyGeneration || b.ActiveIndex[slot] < 0) continue;
                coupling.Track(slot);
                if (b.Type[slot] == BodyType.Dynamic) coupling.Carry(slot, body);
            }
        }
    }
}
