using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Contacts with other soft bodies inside the Newton step. Each vertex-triangle pair of
    /// <see cref="SoftSoftContacts"/> that involves this body (its vertex against another body's
    /// triangle, or another body's vertex against its triangle) and presses where the step is
    /// linearised becomes a term of G:
    /// <code>
    /// E_c = m_o / (2 h^2) max(0, g)^2,   g = r - n . (p - q)
    /// </code>
    /// with p the vertex, q its projection on the triangle, n the triangle's normal, r the
    /// contact distance, the other body's side held where its motion alone takes it in the
    /// substep (its position if it has already stepped this substep, else its prediction) and
    /// m_o that side's mass along n: 1 / sum b_k^2 w_k for a triangle (b its barycentric
    /// weights), 1 / w for a vertex, each vertex's inverse mass multiplied by the number of
    /// this body's pairs it takes part in (its mass shared among them). That is the other side
    /// eliminated from a frictionless contact between the two (its point moves only along n,
    /// to meet this body, at the cost m_o / (2 h^2) |move|^2): this body's step sees the
    /// other one's inertia, as a dynamic rigid body's added mass. After the iterations the
    /// other side takes the impulse m_o g along the normal (<see cref="PushSoftBodies"/>): the
    /// force the step's linear model applied to this body, so that the momentum the two
    /// exchange balances (the internal forces of a body sum to zero); the pass after the
    /// substep then resolves what is left and adds friction within a cone that counts it.
    /// Projected only after the step, the push went into the few tets behind each touching
    /// vertex of a stiff body: a Newton box (E 1e6 Pa, nu 0.3) dropped at 3 m/s on a soft slab
    /// stored 320 J of strain for a 36 J motion and was thrown 2.6 m off the slab.
    /// Terms that did not press at the linearisation point are left out rather than held by
    /// their Hessian alone (as the shape contacts' held penalty): such a term resists the
    /// approach with a force the push does not see, and two Newton cubes meeting in zero
    /// gravity lost 22 % of their momentum.
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
        // Per term: the pair, this body's vertices (up to three, -1 unused) and weights, the other
        // body and its vertices and weights, the direction d with g(x) = c + d . sum_j beta_j x_j,
        // the constant c, the stiffness m_o / h^2 and the other side's mass m_o (0: immovable).
        int _softTerms;
        int[] _softPair = Array.Empty<int>();
        int[] _softOwn = Array.Empty<int>(), _softOtherVertex = Array.Empty<int>();
        Vector3[] _softOwnWeight = Array.Empty<Vector3>(), _softOtherWeight = Array.Empty<Vector3>();
        SoftBody?[] _softOther = Array.Empty<SoftBody?>();
        Vector3[] _softDirection = Array.Empty<Vector3>();
        double[] _softC = Array.Empty<double>(), _softK = Array.Empty<double>(), _softMass = Array.Empty<double>();
        // Per vertex of the other body being counted: how many of this body's terms it is in.
        int[] _sharing = Array.Empty<int>();

        /// <summary>Gathers the soft contact terms at the iterate <paramref name="x"/> and adds them to the system.</summary>
        void AddSoftContacts(SoftBody body, Vector3[] x, float h, double invH2)
        {
            _softTerms = 0;
            SoftSoftContacts? pairs = body.SoftPairs;
            if (pairs == null) return;
            for (int k = 0; k < pairs.PairCount; k++)
            {
                ref SoftSoftContacts.Pair pair = ref pairs[k];
                if (pair.VertexBody == body) GatherVertexTerm(body, x, ref pair, k, h);
                else if (pair.TriangleBody == body) GatherTriangleTerm(body, x, ref pair, k, h);
            }
            ShareMasses(body, invH2);
            for (int t = 0; t < _softTerms; t++) AssembleSoftTerm(t, x);
        }

        /// <summary>Where the other body's vertex <paramref name="v"/> stands at the end of the substep by its own motion, and where it started it.</summary>
        static Vector3 OtherAt(SoftBody body, SoftBody other, int v, float h, out Vector3 start)
        {
            if (other.SubstepsBegun >= body.SubstepsBegun)
            {
                start = other.XPrev[v];
                return other.X[v];
            }
            start = other.X[v];
            if (other.W[v] == 0f) return other.X[v];
            Vector3 g = other.World.Gravity * other.GravityScale;
            return other.X[v] + (other.V[v] + g * h) * h;
        }

        // This body's vertex against the other body's triangle: g = c - n . x_i, c = r + n . q.
        void GatherVertexTerm(SoftBody body, Vector3[] x, ref SoftSoftContacts.Pair pair, int index, float h)
        {
            SoftBody other = pair.TriangleBody;
            int i = pair.Vertex;
            if (_fixed[i]) return;
            Vector3 a = OtherAt(body, other, pair.T0, h, out Vector3 a0);
            Vector3 b = OtherAt(body, other, pair.T1, h, out _);
            Vector3 c = OtherAt(body, other, pair.T2, h, out _);
            Vector3 n = Vector3.Cross(b - a, c - a);
            float area2 = n.Length();
            if (area2 < 1e-12f) return;
            n /= area2;
            float before = Vector3.Dot(n, body.XPrev[i] - a0);
            if (other.IsShell && before < 0f)
            {
                n = -n;
                before = -before;
            }
            if (before < -pair.Thickness) return; // came from behind a volume body's surface
            Vector3 p = x[i];
            float height = Vector3.Dot(n, p - a);
            if (!(height < pair.Thickness)) return; // not pressing at the step's linearisation point
            Vector3 closest = TriangleClosestPoint.Find(p, a, b, c, out Vector3 weights);
            if ((p - height * n - closest).LengthSquared() > 1e-10f) return; // beside the face
            int t = NewSoftTerm();
            _softPair[t] = index;
            SetOwn(t, i, -1, -1, new Vector3(1f, 0f, 0f));
            _softOther[t] = other;
            _softOtherVertex[3 * t] = pair.T0; _softOtherVertex[3 * t + 1] = pair.T1; _softOtherVertex[3 * t + 2] = pair.T2;
            _softOtherWeight[t] = weights;
            _softDirection[t] = -n;
            _softC[t] = pair.Thickness + Vector3.Dot(n, closest);
        }

        // The other body's vertex against this body's triangle: g = c + n . sum_k b_k x_k, c = r - n . p.
        void GatherTriangleTerm(SoftBody body, Vector3[] x, ref SoftSoftContacts.Pair pair, int index, float h)
        {
            SoftBody other = pair.VertexBody;
            int i0 = pair.T0, i1 = pair.T1, i2 = pair.T2;
            if (_fixed[i0] && _fixed[i1] && _fixed[i2]) return;
            Vector3 a = x[i0], b = x[i1], c = x[i2];
            Vector3 n = Vector3.Cross(b - a, c - a);
            float area2 = n.Length();
            if (area2 < 1e-12f) return;
            n /= area2;
            Vector3 p = OtherAt(body, other, pair.Vertex, h, out Vector3 p0);
            float before = Vector3.Dot(n, p0 - body.XPrev[i0]);
            if (body.IsShell && before < 0f)
            {
                n = -n;
                before = -before;
            }
            if (before < -pair.Thickness) return;
            float height = Vector3.Dot(n, p - a);
            if (!(height < pair.Thickness)) return;
            Vector3 closest = TriangleClosestPoint.Find(p, a, b, c, out Vector3 weights);
            if ((p - height * n - closest).LengthSquared() > 1e-10f) return;
            int t = NewSoftTerm();
            _softPair[t] = index;
            SetOwn(t, i0, i1, i2, weights);
            _softOther[t] = other;
            _softOtherVertex[3 * t] = pair.Vertex; _softOtherVertex[3 * t + 1] = -1; _softOtherVertex[3 * t + 2] = -1;
            _softOtherWeight[t] = new Vector3(1f, 0f, 0f);
            _softDirection[t] = n;
            _softC[t] = pair.Thickness - Vector3.Dot(n, p);
        }

        void SetOwn(int t, int v0, int v1, int v2, Vector3 weights)
        {
            _softOwn[3 * t] = v0; _softOwn[3 * t + 1] = v1; _softOwn[3 * t + 2] = v2;
            _softOwnWeight[t] = weights;
        }

        int NewSoftTerm()
        {
            if (_softTerms == _softPair.Length)
            {
                int size = Math.Max(32, 2 * _softTerms);
                Array.Resize(ref _softPair, size);
                Array.Resize(ref _softOwn, 3 * size);
                Array.Resize(ref _softOtherVertex, 3 * size);
                Array.Resize(ref _softOwnWeight, size);
                Array.Resize(ref _softOtherWeight, size);
                Array.Resize(ref _softOther, size);
                Array.Resize(ref _softDirection, size);
                Array.Resize(ref _softC, size);
                Array.Resize(ref _softK, size);
                Array.Resize(ref _softMass, size);
            }
            return _softTerms++;
        }

        static float Weight(Vector3 w, int j) => j == 0 ? w.X : j == 1 ? w.Y : w.Z;

        /// <summary>
        /// Each term's other-side mass m_o, with every vertex of the other body shared among the
        /// terms it is in (so a light slab under a box is not counted once per touching vertex),
        /// and its stiffness m_o / h^2. An other side that cannot move (pinned) is held by a stiff
        /// spring instead, as an immovable shape is.
        /// </summary>
        void ShareMasses(SoftBody body, double invH2)
        {
            for (int start = 0; start < _softTerms;)
            {
                SoftBody other = _softOther[start]!;
                int end = start;
                while (end < _softTerms && _softOther[end] == other) end++;
                if (_sharing.Length < other.X.Length) _sharing = new int[other.X.Length];
                for (int t = start; t < end; t++)
                    for (int j = 0; j < 3; j++)
                        if (_softOtherVertex[3 * t + j] >= 0) _sharing[_softOtherVertex[3 * t + j]]++;
                for (int t = start; t < end; t++)
                {
                    double inverse = 0;
                    for (int j = 0; j < 3; j++)
                    {
                        int v = _softOtherVertex[3 * t + j];
                        if (v < 0) continue;
                        double w = Weight(_softOtherWeight[t], j);
                        inverse += w * w * other.W[v] * _sharing[v];
                    }
                    if (inverse > 0)
                    {
                        _softMass[t] = 1.0 / inverse;
                        _softK[t] = _softMass[t] * invH2;
                    }
                    else
                    {
                        double own = 0;
                        for (int j = 0; j < 3; j++)
                            if (_softOwn[3 * t + j] >= 0) own += Weight(_softOwnWeight[t], j) * body.M[_softOwn[3 * t + j]];
                        _softMass[t] = 0;
                        _softK[t] = 1e4 * own * invH2;
                    }
                }
                for (int t = start; t < end; t++)
                    for (int j = 0; j < 3; j++)
                        if (_softOtherVertex[3 * t + j] >= 0) _sharing[_softOtherVertex[3 * t + j]] = 0;
                start = end;
            }
        }

        double SoftGap(int t, Vector3[] x)
        {
            Vector3 w = _softOwnWeight[t], d = _softDirection[t];
            double g = _softC[t];
            for (int j = 0; j < 3; j++)
            {
                int v = _softOwn[3 * t + j];
                if (v >= 0) g += Weight(w, j) * (double)Vector3.Dot(d, x[v]);
            }
            return g;
        }

        // Adds term t's gradient k g beta_j d and its Hessian k beta_j beta_l d d^T.
        void AssembleSoftTerm(int t, Vector3[] x)
        {
            double k = _softK[t], g = SoftGap(t, x);
            Vector3 w = _softOwnWeight[t], d = _softDirection[t];
            for (int j = 0; j < 3; j++)
            {
                int vj = _softOwn[3 * t + j];
                if (vj < 0 || _fixed[vj]) continue;
                int rj = 3 * _order[vj];
                double bj = Weight(w, j);
                for (int a = 0; a < 3; a++) _rhs[rj + a] -= k * g * bj * Component(d, a);
                for (int l = 0; l < 3; l++)
                {
                    int vl = _softOwn[3 * t + l];
                    if (vl < 0 || _fixed[vl]) continue;
                    int rl = 3 * _order[vl];
                    double bjl = k * bj * Weight(w, l);
                    for (int a = 0; a < 3; a++)
                        for (int c = 0; c < 3; c++)
                            if (rj + a >= rl + c) At(rj + a, rl + c) += bjl * Component(d, a) * Component(d, c);
                }
            }
        }

        /// <summary>The soft contact terms' part of G at <paramref name="x"/>.</summary>
        double SoftContactEnergy(Vector3[] x)
        {
            double e = 0;
            for (int t = 0; t < _softTerms; t++)
            {
                double g = SoftGap(t, x);
                if (g > 0) e += 0.5 * _softK[t] * g * g;
            }
            return e;
        }

        /// <summary>
        /// After the substep's Newton iterations: each term of the last one that still presses
        /// hands the other body the impulse m_o g along its direction at the body's final
        /// positions (see the class summary), as a change of velocity (and
        /// of position, where an XPBD body has already stepped this substep: a Newton body moved
        /// here would store the move in the tets behind the vertex), and records it on its pair
        /// for the friction of the pass after the substep. A term the step carried past the
        /// contact (g &lt; 0: its linear model pulled) hands nothing: handing the pull on as well
        /// kept the momentum to the last digit but let a Newton box (E 1e7 Pa) landing at 3 m/s
        /// on a Newton slab creep off it.
        /// </summary>
        public void PushSoftBodies(SoftBody body, float h)
        {
            float invH = 1f / h;
            for (int t = 0; t < _softTerms; t++)
            {
                if (!(_softMass[t] > 0)) continue;
                double g = SoftGap(t, body.X);
                if (!(g > 0)) continue;
                float impulse = (float)(_softMass[t] * g);
                SoftBody other = _softOther[t]!;
                bool stepped = other.SubstepsBegun >= body.SubstepsBegun;
                Vector3 d = _softDirection[t], w = _softOtherWeight[t];
                for (int j = 0; j < 3; j++)
                {
                    int v = _softOtherVertex[3 * t + j];
                    if (v < 0 || other.W[v] == 0f) continue;
                    Vector3 move = other.W[v] * Weight(w, j) * impulse * d;
                    if (stepped && other.Solver != SoftSolver.Newton) other.X[v] += move;
                    other.V[v] += move * invH;
                }
                body.SoftPairs![_softPair[t]].Pushed += impulse;
            }
        }
    }
}
