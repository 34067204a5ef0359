using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// <see cref="SoftSolver.Newton"/>: implicit (backward) Euler, each iteration one Newton step
    /// on the incremental potential of the whole body, solved directly:
    /// <code>
    /// G(x) = sum_i m_i / (2 h^2) |x_i - y_i|^2 + sum_e V_e Psi(F_e),   y = x_n + h v_n + h^2 g
    /// (M / h^2 + (1 + tau / h) K) dx = -(M / h^2 (x - y) + f_int(x) + tau / h K (x - x_n))
    /// </code>
    /// with K the tangent stiffness (the exact Hessian of the elastic energy, assembled from
    /// <see cref="NeoHookeanTangent"/>) and tau the stiffness-proportional damping time (x - x_n
    /// in the damping term is taken less the body's rigid motion: see FitRigidMotion). One
    /// Newton step per substep is the linearised implicit Euler of Baraff and Witkin (1998);
    /// more iterations converge the step. Being global, it carries a load across a stiff body in
    /// one solve, where Gauss-Seidel (XPBD, or vertex block descent) needs as many sweeps as the
    /// stiffness contrast: a 1 m cantilever at E = 1e9 Pa sags 0.33 mm (its converged answer)
    /// instead of 0.11 m.
    /// <para>
    /// The system is stored as a symmetric band (vertices renumbered by reverse Cuthill-McKee so
    /// that the band is narrow) and factored by band Cholesky, O(3n b^2) for n vertices and a
    /// band of b: for small and medium bodies (a few hundred vertices). The element Hessian of
    /// the stable energy is indefinite under strong compression; a non-positive pivot adds a
    /// diagonal shift (x4 per retry) until the factorisation succeeds, which keeps the step a
    /// descent direction. Pinned vertices are Dirichlet rows. A dynamic body the body touches
    /// takes part in the step as added mass on the touching vertices (see Step); other contacts
    /// and attachments are projected after each Newton step as for XPBD. Allocates once per
    /// body, nothing per step.
    /// </para>
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
        readonly int _n, _dofs, _band;   // vertices, 3 n, half-bandwidth in DOFs
        readonly int[] _order;           // new index of each vertex
        readonly double[] _matrix;       // row i holds columns i - _band .. i, at i * (_band + 1) + (col - i + _band)
        readonly double[] _saved;
        readonly double[] _rhs, _gradient;
        readonly Vector3[] _trial;
        readonly Vector3[] _lag;         // per vertex: x - x_n less the body's rigid motion (the damped part; see FitRigidMotion)
        readonly double[] _rows;         // per tet, its four r_a (12 doubles), refreshed from the rest inverse each assembly
        readonly NeoHookeanTangent _tangent;
        readonly float _reach;           // the most a vertex may move in one Newton step: a quarter of the shortest rest edge
        // Contacts with dynamic bodies in this Newton step (see Step): vertex, normal, point,
        // body slot, friction coefficient, the share of the body's mass each carries, and where
        // the body's motion alone would take the vertex. _owners: the distinct body slots.
        readonly int[] _contactVertex, _contactOwner, _owners;
        readonly Vector3[] _contactNormal, _contactPoint, _contactGoal;
        readonly float[] _contactFriction;
        readonly double[] _contactMass;
        int _contacts;
        // Vertices inside an immovable shape where the step starts: a one-sided stiff spring to
        // the shape's surface in the step (see Step).
        readonly int[] _overlapVertex;
        readonly Vector3[] _overlapNormal, _overlapPoint;
        readonly double[] _overlapStiffness, _overlapGap;
        readonly bool[] _overlapping;
        int _overlaps;
        // The fraction of the solved step the line search took (0: none), and the shift
        // KeepMomentum added to every vertex after it.
        double _taken;
        Vector3 _shift;
        // Vertices held along a shape's normal by the penalty of Step (no force where the step
        // starts): vertex, normal, stiffness; for the friction support (ReportSupport).
        readonly int[] _heldVertex;
        readonly Vector3[] _heldNormal;
        readonly double[] _heldStiffness;
        int _helds;
        // Vertices static friction held in the last substep as part of a resting patch
        // (ShapeContactSolver.Sticks): a stiff spring across the normal to where the shape's
        // surface carries the vertex, counted in G (see Stick): vertex, normal, anchor, stiffness.
        readonly int[] _stickVertex;
        readonly Vector3[] _stickNormal, _stickAnchor;
        readonly double[] _stickStiffness;
        int _sticks;
        // Per vertex in an assembly: the stiffness of its overlap or held spring (0: none).
        readonly double[] _penalty;

        public ImplicitNewtonSolver(SoftBody body)
        {
            _n = body.X.Length;
            _dofs = 3 * _n;
            _order = ReverseCuthillMcKee(body.Tets, _n);
            int band = 0;
            foreach (TetElement t in body.Tets)
            {
                int lo = Math.Min(Math.Min(_order[t.A], _order[t.B]), Math.Min(_order[t.C], _order[t.D]));
                int hi = Math.Max(Math.Max(_order[t.A], _order[t.B]), Math.Max(_order[t.C], _order[t.D]));
                band = Math.Max(band, hi - lo);
            }
            _band = 3 * band + 2;
            _matrix = new double[_dofs * (_band + 1)];
            _saved = new double[_matrix.Length];
            _rhs = new double[_dofs];
            _gradient = new double[_dofs];
            _trial = new Vector3[_n];
            _lag = new Vector3[_n];
            _rows = new double[12];
            _tangent = new NeoHookeanTangent(body.Material);
            float shortest = float.MaxValue;
            ReadOnlySpan<Vector3> rest = body.Mesh.Vertices;
            foreach (TetElement t in body.Tets)
            {
                shortest = MathF.Min(shortest, MathF.Min(Vector3.Distance(rest[t.A], rest[t.B]), Vector3.Distance(rest[t.A], rest[t.C])));
                shortest = MathF.Min(shortest, MathF.Min(Vector3.Distance(rest[t.A], rest[t.D]), Vector3.Distance(rest[t.B], rest[t.C])));
                shortest = MathF.Min(shortest, MathF.Min(Vector3.Distance(rest[t.B], rest[t.D]), Vector3.Distance(rest[t.C], rest[t.D])));
            }
            _reach = 0.25f * shortest;
            _contactVertex = new int[_n];
            _contactOwner = new int[_n];
            _contactNormal = new Vector3[_n];
            _contactPoint = new Vector3[_n];
            _contactMass = new double[_n];
            _contactGoal = new Vector3[_n];
            _contactFriction = new float[_n];
            _owners = new int[_n];
            _overlapVertex = new int[_n];
            _overlapNormal = new Vector3[_n];
            _overlapPoint = new Vector3[_n];
            _overlapStiffness = new double[_n];
            _overlapGap = new double[_n];
            _overlapping = new bool[_n];
            _heldVertex = new int[_n];
            _heldNormal = new Vector3[_n];
            _heldStiffness = new double[_n];
            _stickVertex = new int[_n];
            _stickNormal = new Vector3[_n];
            _stickAnchor = new Vector3[_n];
            _stickStiffness = new double[_n];
            _penalty = new double[_n];
        }

        // Whether the last Factor needed a diagonal shift (the matrix was not positive definite).
        bool _shifted;
        ref double At(int row, int col) => ref _matrix[row * (_band + 1) + col - row + _band];

        /// <summary>One Newton step towards the minimum of G for a substep of <paramref name="h"/> with inertial targets <paramref name="y"/>.</summary>
        public void Step(SoftBody body, Vector3[] y, float h, RigidCoupling coupling)
        {
            Vector3[] x = body.X, xStart = body.XPrev;
            float[] m = body.M;
            double invH2 = 1.0 / ((double)h * h);
            _contacts = 0; // gathered below; G before then counts inertia, strain and attachments
            _softTerms = 0;
            _overlaps = 0;
            _helds = 0;
            _sticks = 0;
            Array.Clear(_overlapping, 0, _n);
            BeginAttachments(body, x, y, invH2);
            StartFromPrevious(body, x, y, invH2);
            Assemble(body, y, h, invH2, coupling, false);
            for (int k = 0; k < _dofs; k++) _gradient[k] = -_rhs[k];
            bool factored = Factor();
            if (factored && _shifted)
            {
                // The exact Hessian is indefinite beyond what the inertia holds: assembled again
                // with each element's tangent made definite (DefiniteTangent), not shifted.
                Assemble(body, y, h, invH2, coupling, true);
                for (int k = 0; k < _dofs; k++) _gradient[k] = -_rhs[k];
                factored = Factor();
            }
            if (!factored)
            {
                PushBodies(body, x, h, coupling); // no step from a matrix that cannot be factored: keep x
                return;
            }
            Solve(_rhs, 0);
            if (_bodyCount > 0 && !SolveBodies())
            {
                PushBodies(body, x, h, coupling); // the bodies' system is singular: keep x
                return;
            }

            // Backtracking (Armijo) on G: a full Newton step on a non-convex energy can overshoot
            // into an inverted state (a jelly hitting the ground exploded without it).
            double slope = 0;
            for (int k = 0; k < _dofs; k++) slope += _gradient[k] * _rhs[k];
            if (_bodyCount > 0) slope += BodySlope();
            if (!(slope < 0))
            {
                PushBodies(body, x, h, coupling); // not a descent direction (round-off at a minimum): keep x
                return;
            }
            double g0 = Energy(body, x, y, invH2);
            // A trust region: no vertex moves more than a quarter of the shortest edge in one
            // step, so a step cannot jump a tet through inversion (with lambda in the thousands
            // of mu, float positions make G too coarse for the line search alone to stop it). A
            // step that goes further is damped first (Damp), and what is still too long scaled.
            double largest = LargestMove(out double rms);
            if (largest > _reach && _bodyCount == 0 && largest > Outlier * rms)
            {
                if (!Damp(body, invH2, ref largest))
                {
                    PushBodies(body, x, h, coupling);
                    return;
                }
                slope = 0;
                for (int k = 0; k < _dofs; k++) slope += _gradient[k] * _rhs[k];
            }
            if (_bodyCount > 0) largest = Math.Max(largest, LargestCarried());
            double step = largest > _reach ? _reach / largest : 1;
            _taken = 0;
            _shift = Vector3.Zero;
            for (int tries = 0; tries < 12; tries++, step *= 0.5)
            {
                for (int i = 0; i < _n; i++)
                {
                    int r = 3 * _order[i];
                    _trial[i] = _fixed[i] ? x[i] : x[i] + (float)step * new Vector3((float)_rhs[r], (float)_rhs[r + 1], (float)_rhs[r + 2]);
                }
                if (_bodyCount > 0) CarryTrial(x, (float)step);
                double g = Energy(body, _trial, y, invH2) + (_bodyCount > 0 ? BodyEnergy(step, invH2) : 0);
                if (g <= g0 + 1e-4 * step * slope)
                {
                    Array.Copy(_trial, x, _n);
                    if (_bodyCount > 0) PushCarriers((float)step, h, coupling);
                    _taken = step;
                    break;
                }
            }
            if (_taken > 0) KeepContactSpin(body, x, y);
            KeepMomentum(body, x, y, (float)_taken, h, coupling);
            PushBodies(body, x, h, coupling);
            ReportSupport(body, x, y, h);
            ReportSticks(body, x, y, h);
        }

        /// <summary>
        /// Holds vertex <paramref name="i"/> across <paramref name="n"/> by a spring of stiffness
        /// <paramref name="k"/> to its anchor, when it rests on an immovable shape
        /// (ShapeContactSolver.Sticks): the anchor is where it started the substep, carried by
        /// the shape's surface; the spring's energy is part of G. Static friction is then part of the
        /// step, as the ground springs are along the normal: the body hangs on its contacts
        /// inside the solve. Left to the contact pass after the step, friction pulled back only
        /// the touching vertices while the step had moved the whole body down the slope, the
        /// elastic pull between them read as more slip every substep, and a resting cube crept
        /// (E 1e8 Pa at 20 degrees, mu 0.5: 5.1 cm/s; nu 0.49 at 30 degrees, mu 0.7: 3.7 cm/s).
        /// </summary>
        void Stick(int i, int r, Vector3 n, Vector3 x, Vector3 anchor, double k)
        {
            Vector3 d = x - anchor;
            d -= Vector3.Dot(d, n) * n;
            for (int a = 0; a < 3; a++)
            {
                _rhs[r + a] -= k * Component(d, a);
                for (int b = 0; b <= a; b++) At(r + a, r + b) += k * ((a == b ? 1.0 : 0.0) - Component(n, a) * Component(n, b));
            }
            _stickVertex[_sticks] = i;
            _stickNormal[_sticks] = n;
            _stickAnchor[_sticks] = anchor;
            _stickStiffness[_sticks++] = k;
        }

        // The sticking springs' part of G: 1/2 k |(x - anchor) across the normal|^2.
        double StickEnergy(Vector3[] x)
        {
            double e = 0;
            for (int c = 0; c < _sticks; c++)
            {
                Vector3 d = x[_stickVertex[c]] - _stickAnchor[c];
                d -= Vector3.Dot(d, _stickNormal[c]) * _stickNormal[c];
                e += 0.5 * _stickStiffness[c] * d.LengthSquared();
            }
            return e;
        }

        /// <summary>
        /// The friction impulse (kg m) the sticking springs carried in the step, along the way they
        /// held their vertices back, for the patch's friction cone
        /// (<see cref="ShapeContactSolver.Stuck"/>, <see cref="ShapeContactSolver.Sticks"/>).
        /// </summary>
        void ReportSticks(SoftBody body, Vector3[] x, Vector3[] y, float h)
        {
            if (_sticks == 0) return;
            double h2 = (double)h * h;
            // The springs are stiff enough that their stretch is below the positions' float
            // resolution (a 27 kg cube resting on a slope: a few nanometres), so their own
            // measures read zero, or a whole step's friction on one vertex. What the body took
            // across the normal in the step is what they all held together: -sum_i m_i (x_i - y_i)
            // across their mean normal (the elements' forces cancel in it, as in ReportSupport),
            // spread over the held vertices by mass. Where the normals disagree (a body wedged
            // between two shapes) the springs' own measures stand.
            Vector3 normal = Vector3.Zero;
            double held = 0;
            float[] m = body.M;
            for (int c = 0; c < _sticks; c++)
            {
                normal += _stickNormal[c];
                held += m[_stickVertex[c]];
            }
            float agree = normal.Length();
            if (!(agree > 0.5f * _sticks) || !(held > 0))
            {
                for (int c = 0; c < _sticks; c++) body.Contacts.Stuck(_stickVertex[c], StickImpulse(c, x, h2));
                return;
            }
            normal /= agree;
            Vector3 total = Vector3.Zero;
            for (int i = 0; i < _n; i++) if (!_fixed[i]) total -= m[i] * (x[i] - y[i]);
            total -= Vector3.Dot(total, normal) * normal;
            for (int c = 0; c < _sticks; c++)
            {
                int i = _stickVertex[c];
                body.Contacts.Stuck(i, (float)(m[i] / held) * total);
            }
        }

        Vector3 StickImpulse(int c, Vector3[] x, double h2)
        {
            Vector3 d = x[_stickVertex[c]] - _stickAnchor[c];
            d -= Vector3.Dot(d, _stickNormal[c]) * _stickNormal[c];
            return (float)(_stickStiffness[c] * h2) * d;
        }

        /// <summary>
        /// Assembles the Newton system at the current positions: inertia, the elements' gradient
        /// and Hessian (each element's tangent made definite when <paramref name="project"/>),
        /// the springs to immovable shapes, the shares of dynamic bodies, the attached bodies'
        /// coupling, other soft bodies, and the Dirichlet rows.
        /// </summary>
        void Assemble(SoftBody body, Vector3[] y, float h, double invH2, RigidCoupling coupling, bool project)
        {
            Vector3[] x = body.X, xStart = body.XPrev;
            float[] m = body.M;
            _overlaps = 0;
            _helds = 0;
            _sticks = 0;
            Array.Clear(_overlapping, 0, _n);
            Array.Clear(_penalty, 0, _n);
            Array.Clear(_matrix, 0, _matrix.Length);
            Array.Clear(_rhs, 0, _rhs.Length);
            double damping = body.DampingTime > 0f ? body.DampingTime / (double)h : 0.0;
            if (damping > 0)
            {
                FitRigidMotion(body, x, xStart); // leaves x - x_n in _lag
                for (int i = 0; i < _n; i++) _lag[i] -= RigidDisplacement(xStart[i]);
            }
            for (int i = 0; i < _n; i++)
            {
                int r = 3 * _order[i];
                double inertia = m[i] * invH2;
                for (int k = 0; k < 3; k++) At(r + k, r + k) += inertia;
                Vector3 d = x[i] - y[i];
                _rhs[r] -= inertia * d.X;
                _rhs[r + 1] -= inertia * d.Y;
                _rhs[r + 2] -= inertia * d.Z;
            }

            Span<double> f = stackalloc double[9];
            Span<double> p = stackalloc double[9];
            Span<double> c = stackalloc double[81];
            Span<int> v = stackalloc int[4];
            Span<double> rest = _rows;
            TetElement[] tets = body.Tets;
            for (int e = 0; e < tets.Length; e++)
            {
                ref TetElement t = ref tets[e];
                v[0] = t.A; v[1] = t.B; v[2] = t.C; v[3] = t.D;
                Vector3 r1 = t.RestInverse.R0, r2 = t.RestInverse.R1, r3 = t.RestInverse.R2, r0 = -(r1 + r2 + r3);
                Set(rest, 0, r0); Set(rest, 1, r1); Set(rest, 2, r2); Set(rest, 3, r3);
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                    {
                        double s = 0;
                        for (int a = 0; a < 4; a++) s += Component(x[v[a]], i) * rest[3 * a + j];
                        f[3 * i + j] = s;
                    }
                double volume = t.RestVolume;
                _tangent.Stress(f, p);
                _tangent.Tangent(f, c);
                if (project) DefiniteTangent.Project(c);
                for (int a = 0; a < 4; a++)
                {
                    int ra = 3 * _order[v[a]];
                    for (int i = 0; i < 3; i++)
                    {
                        double s = 0;
                        for (int j = 0; j < 3; j++) s += p[3 * i + j] * rest[3 * a + j];
                        _rhs[ra + i] -= volume * s;
                    }
                    for (int b = 0; b < 4; b++)
                    {
                        int rb = 3 * _order[v[b]];
                        Vector3 lag = damping > 0 ? _lag[v[b]] : Vector3.Zero;
                        for (int i = 0; i < 3; i++)
                            for (int l = 0; l < 3; l++)
                            {
                                double s = 0;
                                for (int j = 0; j < 3; j++)
                                {
                                    double aj = rest[3 * a + j];
                                    for (int q = 0; q < 3; q++) s += aj * c[9 * (3 * i + j) + 3 * l + q] * rest[3 * b + q];
                                }
                                double k = volume * s;
                                if (damping > 0) _rhs[ra + i] -= damping * k * Component(lag, l);
                                if (ra + i >= rb + l) At(ra + i, rb + l) += (1 + damping) * k;
                            }
                    }
                }
            }

            // A vertex inside an immovable shape where the step starts is held by a one-sided
            // spring to the shape's surface (the plane at the deepest overlap; the stiffness of
            // the held vertices below, from the diagonal before their penalty is added), counted
            // in G: the step pushes it out and spreads the strain over the body, where the
            // contact pass after the step pushed it out alone and stored the strain in the few
            // tets behind it (a nu 0.49-0.4999 cube thrown at the ground at 3-10 m/s: min J
            // 0.15-0.23; with the spring 0.43-0.60; a 3.5 kg beam at E 2e9 landing at 5.4 m/s:
            // 5e4 J of strain stored in one substep, 3.4e3 J with it, soft fuzz seed 564).
            if (body.CollideWithShapes)
                for (int i = 0; i < _n; i++)
                {
                    if (_fixed[i] || !body.Contacts.ImmovableOverlap(body.World, body, x[i], out Vector3 outward, out Vector3 surface)) continue;
                    int r = 3 * _order[i];
                    double k = 1e4 * m[i] * invH2 + 1e3 * At(r, r);
                    double gap = Vector3.Dot(x[i] - surface, outward);
                    for (int a = 0; a < 3; a++)
                    {
                        _rhs[r + a] -= k * gap * Component(outward, a);
                        for (int b = 0; b <= a; b++) At(r + a, r + b) += k * Component(outward, a) * Component(outward, b);
                    }
                    _overlapping[i] = true;
                    _overlapVertex[_overlaps] = i;
                    _overlapNormal[_overlaps] = outward;
                    _overlapPoint[_overlaps] = surface;
                    _overlapGap[_overlaps] = gap;
                    _overlapStiffness[_overlaps++] = k;
                    _penalty[i] = k;
                }

            // Vertices an immovable shape (static or kinematic) pushed in this substep or the last
            // are held along the push normal by
            // a stiff penalty k n n^T with no force at the current position: the Newton step
            // cannot drive them back into the shape, while the contact pass after it pushes out
            // what is still inside. Without it the step undid the contact every substep and a
            // nearly incompressible jelly (nu = 0.4999) inverted at impact.
            if (body.CollideWithShapes)
                for (int i = 0; i < _n; i++)
                {
                    // Not those the overlap springs above hold: they have their stiffness along
                    // the normal already, and a second k n n^T against the spring's one k gap
                    // halved the step out of the shape (the contact pass after the step then
                    // pushed the other half out alone: a 3.5 kg beam at E 2e9 Pa landing at
                    // 5.4 m/s stored 3.4e3 J in its tets, soft fuzz seed 564; 1.4 J now).
                    if (_fixed[i] || _overlapping[i] || !body.Contacts.Touches(i, out Vector3 normal)) continue;
                    int r = 3 * _order[i];
                    double k = 1e4 * m[i] * invH2 + 1e3 * At(r, r);
                    for (int a = 0; a < 3; a++)
                        for (int b = 0; b <= a; b++) At(r + a, r + b) += k * Component(normal, a) * Component(normal, b);
                    _heldVertex[_helds] = i;
                    _heldNormal[_helds] = normal;
                    _heldStiffness[_helds++] = k;
                    _penalty[i] = k;
                }

            // Dynamic bodies in the solve (added mass): each vertex touching a dynamic body carries
            // an equal share of the body's generalised mass at the contact, 1 / (n w_b), with the
            // body's own motion as its inertial target (along the normal: the body's surface at
            // its pose for the end of the substep; across it: the surface point's motion, as
            // sticking friction), so the step finds where the soft body and the rigid one meet,
            // the load carried across a stiff body in the same solve. The shares' momentum change
            // then goes to the body (PushBodies), the tangential part within the friction cone.
            // Projected only after the step, a contact had only the vertex's own mass to push on:
            // a 100 kg crate dropped 0.5 m on a slab of E 1e8 Pa crushed it to the volume floor
            // and was thrown off spinning at 20 rad/s, and a 1 t crate on E 1e6-1e8 at nu 0.49
            // inverted tets to J -8.
            _contacts = body.CollideWithShapes ? body.Contacts.DynamicContacts(body.World, body, _contactVertex, _contactNormal, _contactPoint, _contactOwner, _contactFriction) : 0;
            int owners = 0;
            for (int q = 0; q < _contacts; q++)
            {
                int o = 0;
                while (o < owners && _owners[o] != _contactOwner[q]) o++;
                if (o == owners) _owners[owners++] = _contactOwner[q];
            }
            for (int o = 0; o < owners; o++)
            {
                int owner = _owners[o], sharing = 0;
                for (int q = 0; q < _contacts; q++) if (_contactOwner[q] == owner) sharing++;
                for (int q = 0; q < _contacts; q++)
                {
                    if (_contactOwner[q] != owner) continue;
                    int i = _contactVertex[q];
                    Vector3 n = _contactNormal[q], at = _contactPoint[q];
                    double share = 1.0 / (sharing * (double)coupling.InverseMassAt(owner, at, n));
                    _contactMass[q] = share;
                    Vector3 carried = xStart[i] + coupling.PointVelocity(owner, at) * h;
                    Vector3 goal = carried + (Vector3.Dot(at, n) + body.CollisionRadius - Vector3.Dot(carried, n)) * n;
                    _contactGoal[q] = goal;
                    int r = 3 * _order[i];
                    double k = share * invH2;
                    Vector3 gap = x[i] - goal;
                    for (int a = 0; a < 3; a++)
                    {
                        _rhs[r + a] -= k * Component(gap, a);
                        At(r + a, r + a) += k;
                    }
                }
            }

            if (_bodyCount > 0) CoupleBodies(body, invH2);
            if (body.SoftPairs != null) AddSoftContacts(body, x, h, invH2);

            // A body at rest on immovable shapes alone sticks to them: its vertices within reach of
            // one in the last substep are held across the normal too, as stiffly as along it
            // (see Stick). Not while it touches a dynamic or soft body or carries one: what the
            // body takes across the normal in the step is then not the ground's friction alone
            // (ReportSticks).
            if (body.CollideWithShapes && _contacts == 0 && _softTerms == 0 && _bodyCount == 0)
                for (int i = 0; i < _n; i++)
                {
                    if (_fixed[i] || !body.Contacts.Sticks(i, out Vector3 normal, out Vector3 surfaceVelocity)) continue;
                    int r = 3 * _order[i];
                    double k = _penalty[i] > 0 ? _penalty[i] : 1e4 * m[i] * invH2 + 1e3 * At(r, r);
                    Stick(i, r, normal, x[i], xStart[i] + surfaceVelocity * h, k);
                }

            // Pinned vertices and those attached to immovable bodies: Dirichlet rows (identity, zero step).
            for (int i = 0; i < _n; i++)
            {
                if (!_fixed[i]) continue;
                int r = 3 * _order[i];
                for (int k = 0; k < 3; k++) Pin(r + k);
            }
        }

        /// <summary>
        /// Whether the step took a free vertex into a static or kinematic shape deeper than
        /// <see cref="EnterTolerance"/> where its system held no spring (the overlap springs are
        /// gathered where the step starts). The substep then takes one more Newton step, which
        /// holds that vertex with an overlap spring and spreads its way out over the body;
        /// otherwise the contact pass after the step pushed it out alone and stored the move in
        /// the few tets behind it. Measured on the Newton worlds of the soft fuzz that failed:
        /// seeds 237 (a 3.9e8 Pa box on a soft Newton box, a tet ending at J -0.49), 649 and 681
        /// (very soft Newton boxes under heavy bodies, diverged) pass, the seven others fail as
        /// before; the extra step ran in 0.2-7 % of their substeps (145 of 3,600 in 237).
        /// </summary>
        public bool Entered(SoftBody body, float tolerance)
        {
            if (!body.CollideWithShapes) return false;
            Vector3[] x = body.X;
            for (int i = 0; i < _n; i++)
            {
                if (_fixed[i] || _overlapping[i]) continue;
                if (!body.Contacts.ImmovableOverlap(body.World, body, x[i], out Vector3 outward, out Vector3 surface)) continue;
                if (Vector3.Dot(surface - x[i], outward) > tolerance) return true;
            }
            return false;
        }

        /// <summary>How deep a vertex must have entered a shape for <see cref="Entered"/>: 10 um (round-off of a resting contact is well below).</summary>
        public const float EnterTolerance = 1e-5f;

        /// <summary>
        /// Levenberg-Marquardt damping of a step in which a few vertices would move further than
        /// the trust region (<c>_reach</c>), the longest move more than <see cref="Outlier"/> times
        /// the root mean square one: the inertia of every free vertex is raised by a factor
        /// 1 + lambda (lambda from largest / reach - 1, x4 per retry, at most four times) and the
        /// system is factored and solved again, so the step shrinks most in the modes that are
        /// soft, where scaling the whole step down does not. A nearly incompressible body's
        /// linear tets are stiff in volume and soft in shear: a bottom vertex of a nu = 0.4999
        /// slab, its neighbours pushed up 27 um out of the ground, got a Newton step of 9 cm
        /// sideways (the linear model's way to relieve the volume change); scaled to the trust
        /// region with the whole step it moved 2.5 cm, the slab's tets went to J 0.81 and 6e4 J
        /// of strain, and released over the next steps that energy threw an XPBD box resting on
        /// the slab about (its motion gained up to 663 J; none now). Not for a step whose moves
        /// are all long (a body striking the ground: its whole motion is the inertia the damping
        /// raises, and a nu = 0.49 cube thrown down at 10 m/s, damped at a ratio of 6, reached
        /// min J 0.39 instead of 0.72), nor with rigid bodies in the solve (their coupled system
        /// is solved once). False when the damped matrix cannot be factored (the step is skipped).
        /// </summary>
        bool Damp(SoftBody body, double invH2, ref double largest)
        {
            float[] m = body.M;
            double lambda = largest / _reach - 1, added = 0;
            for (int tries = 0; tries < 4 && largest > _reach; tries++, lambda *= 4)
            {
                Array.Copy(_saved, _matrix, _matrix.Length);
                for (int i = 0; i < _n; i++)
                {
                    if (_fixed[i]) continue;
                    int r = 3 * _order[i];
                    double d = (lambda - added) * m[i] * invH2;
                    for (int k = 0; k < 3; k++) At(r + k, r + k) += d;
                }
                added = lambda;
                if (!Factor()) return false;
                for (int k = 0; k < _dofs; k++) _rhs[k] = -_gradient[k];
                Solve(_rhs, 0);
                largest = LargestMove(out _);
            }
            return true;
        }

        /// <summary>How many times the root mean square move the longest must be for <see cref="Damp"/>: 8 (see there).</summary>
        const double Outlier = 8;

        // The longest move of a free vertex in the step direction (_rhs), and the root mean
        // square move, m.
        double LargestMove(out double rms)
        {
            double largest = 0, sum = 0;
            int count = 0;
            for (int i = 0; i < _n; i++)
            {
                if (_fixed[i]) continue;
                int r = 3 * _order[i];
                double move = _rhs[r] * _rhs[r] + _rhs[r + 1] * _rhs[r + 1] + _rhs[r + 2] * _rhs[r + 2];
                largest = Math.Max(largest, move);
                sum += move;
                count++;
            }
            rms = count > 0 ? Math.Sqrt(sum / count) : 0;
            return Math.Sqrt(largest);
        }

        /// <summary>
        /// The normal impulse each ground spring of the step carried, for the friction of the
        /// contact pass (<see cref="ShapeContactSolver.Support"/>). A spring's own measure, k h^2
        /// times how deep its vertex ends (for a held vertex, how far the step took it into the
        /// shape from its inertial target y), is its force only where the step converged; at a
        /// landing it came out a thousand times the impulse that stopped the body, and the
        /// friction of that one substep stopped a sliding slab dead; resting on a slope it came
        /// out up to 30 % short. So the springs' measures are scaled, together, to the normal
        /// impulse the body as a whole took in the step, sum_i m_i n . (x_i - y_i) along their
        /// mean normal n (internal forces cancel in that sum). Where the springs' normals
        /// disagree (a body pressed between two shapes) their own measures stand.
        /// </summary>
        void ReportSupport(SoftBody body, Vector3[] x, Vector3[] y, float h)
        {
            if (_overlaps == 0 && _helds == 0) return;
            double h2 = (double)h * h, sum = 0;
            Vector3 mean = Vector3.Zero;
            for (int c = 0; c < _overlaps + _helds; c++)
            {
                double f = SpringImpulse(c, x, y, h2, out Vector3 n);
                sum += f;
                mean += (float)f * n;
            }
            if (!(sum > 0)) return;
            double scale = 1;
            float length = mean.Length();
            if (length > 0.5f * sum)
            {
                mean /= length;
                double taken = 0;
                float[] m = body.M;
                for (int i = 0; i < _n; i++) if (!_fixed[i]) taken += m[i] * Vector3.Dot(mean, x[i] - y[i]);
                scale = Math.Max(0, taken) / sum;
            }
            for (int c = 0; c < _overlaps + _helds; c++)
            {
                double f = SpringImpulse(c, x, y, h2, out _);
                if (f > 0) body.Contacts.Support(c < _overlaps ? _overlapVertex[c] : _heldVertex[c - _overlaps], (float)(scale * f));
            }
        }

        // Spring c's own measure of its normal impulse (the overlap springs first, then the held
        // vertices), and its normal.
        double SpringImpulse(int c, Vector3[] x, Vector3[] y, double h2, out Vector3 normal)
        {
            if (c < _overlaps)
            {
                // The gap the step's own (double) solve left, not the one read back from the
                // float positions: the spring (k = 1e4 m / h^2 and more) holds a vertex's share
                // of the weight at a gap of a few nm, below the spacing of floats a few metres
                // from the origin (0.95 um at 10 m, 7.6 um at 100 m). Read from the positions, the
                // measure was a float's rounding: a Newton slab pushed across ground at y = 10 m
                // slid on at 0.75 m/s after 0.33 s (it stops in 0.2 s on ground at y = 0), at
                // 100 m at 0.95 m/s; near the origin too (60 nm at 0.5 m) the measure was noise.
                normal = _overlapNormal[c];
                int r = 3 * _order[_overlapVertex[c]];
                double gap = _overlapGap[c] + _taken * (normal.X * _rhs[r] + normal.Y * _rhs[r + 1] + normal.Z * _rhs[r + 2]) + Vector3.Dot(_shift, normal);
                return gap < 0 ? _overlapStiffness[c] * h2 * -gap : 0;
            }
            c -= _overlaps;
            normal = _heldNormal[c];
            int i = _heldVertex[c];
            double into = -Vector3.Dot(x[i] - y[i], normal);
            return into > 0 ? _heldStiffness[c] * h2 * into : 0;
        }

        /// <summary>
        /// A body held in place somewhere (pinned to the world, or attached to a static or
        /// kinematic body) starts the step at the substep's start positions (the free vertices
        /// where they were before the prediction) when G is lower there than where the iteration
        /// stands. The prediction x + v h + g h^2 moves the free vertices but not the held ones
        /// and strains the elements between them; in a nearly incompressible body that strain is
        /// far from the step's minimum, and the trust region and line search then leave most of
        /// it in place: a classic Neo-Hookean capsule at nu 0.4999 pinned by one end sagged to
        /// J = -9 within 11 steps (soft fuzz seed 154; where the prediction inverts an element
        /// the classic energy is infinite and the line search had nothing to compare against).
        /// Now it hangs at its static sag. The minimum is the same; the 1 m cantilever at
        /// E 1e9 Pa comes within 0.1 % of its converged sag instead of 0.7 %. (Starting there
        /// for free bodies as well, a nu = 0.4999 beam under a 25 kg capsule inverted: seed 241.)
        /// </summary>
        void StartFromPrevious(SoftBody body, Vector3[] x, Vector3[] y, double invH2)
        {
            bool held = false;
            for (int i = 0; i < _n && !held; i++) held = _fixed[i] && _carrier[i] < 0;
            if (!held) return;
            Vector3[] previous = body.XPrev;
            double here = Energy(body, x, y, invH2);
            Array.Copy(x, _trial, _n);
            for (int i = 0; i < _n; i++) if (!_fixed[i]) _trial[i] = previous[i];
            if (Energy(body, _trial, y, invH2) < here) Array.Copy(_trial, x, _n);
        }

        /// <summary>
        /// A free body (nothing pinned, held or touching) ends the step with the momentum its
        /// inertia asks for: the translation d that minimises the inertia term over a uniform
        /// shift, d = -sum m (x - y) / sum m (the carried rigid bodies counted with their mass
        /// and their move in the step), is added to every vertex and carried body. The strain is
        /// unchanged by a shift, so G only falls; a full Newton step has d = 0, but the trust
        /// region and the line search cut short the steps of a stiff body, and each cut-short
        /// step lost part of its momentum: a 0.4 kg box at E 1e9 Pa whipped on a 3 m lever by a
        /// 50 g body turned its pair's momentum by 1.3 kg m/s of 0.5 in two seconds.
        /// </summary>
        void KeepMomentum(SoftBody body, Vector3[] x, Vector3[] y, float taken, float h, RigidCoupling coupling)
        {
            if (_contacts > 0 || _softTerms > 0) return;
            Attachment[] attachments = body.Attachments;
            for (int k = 0; k < attachments.Length; k++) if (_bodyOf[k] == Held) return;
            BodyStorage b = body.World.Bodies;
            for (int beta = 0; beta < _bodyCount; beta++) if ((b.Locks[_bodies[beta]] & AxisLocks.Linear) != 0) return;
            float[] m = body.M;
            double mass = 0;
            Vector3 offset = Vector3.Zero;
            for (int i = 0; i < _n; i++)
            {
                if (body.W[i] == 0f || body.CollideWithShapes && body.Contacts.Touches(i, out _)) return;
                mass += m[i];
                offset += m[i] * (x[i] - y[i]);
            }
            for (int beta = 0; beta < _bodyCount; beta++)
            {
                mass += _bodyMass[beta];
                offset += _bodyMass[beta] * taken * BodyMove(beta);
            }
            if (!(mass > 0)) return;
            Vector3 d = -offset / (float)mass;
            if (!(d.LengthSquared() > 0f) || !Validate.IsFinite(d)) return;
            for (int i = 0; i < _n; i++) x[i] += d;
            _shift = d;
            for (int beta = 0; beta < _bodyCount; beta++) coupling.PushSum(_bodies[beta], _bodyMass[beta] * d, Vector3.Zero, h);
        }

        /// <summary>
        /// A body whose only outside forces in the step are springs along one normal n (resting
        /// or sliding on one face of immovable shapes) ends the step with no angular impulse
        /// about n: neither those springs (along n) nor the strain (internal) can give one, and
        /// gravity acts at the centre of mass. The exact implicit Euler step leaves none; the one
        /// linearised Newton step does, to first order -sum d x K d over the step's moves d
        /// (Documentation~/SoftSolvers.md), and a stiff, nearly incompressible cube sliding down
        /// a slope was turned about the slope's normal at 2.5-3.4 rad/s, its vertices' slips
        /// spread up to 33 degrees about its motion and the friction down the slope 5 % short
        /// (E 1e9 Pa, nu 0.45, 15 degrees: 11 % fast). The body is turned about n through its
        /// centre of mass c by the angle that removes that impulse,
        /// theta = -sum m ((x - c) x (x - y)) . n / sum m |(x - c) x n|^2.
        /// The turn keeps every gap along n and the strain; only the inertia term changes.
        /// </summary>
        void KeepContactSpin(SoftBody body, Vector3[] x, Vector3[] y)
        {
            int springs = _overlaps + _helds;
            if (springs == 0 || _contacts > 0 || _softTerms > 0 || _sticks > 0 || _bodyCount > 0) return;
            Attachment[] attachments = body.Attachments;
            for (int k = 0; k < attachments.Length; k++) if (_bodyOf[k] == Held) return;
            Vector3 sum = Vector3.Zero;
            for (int c = 0; c < _overlaps; c++) sum += _overlapNormal[c];
            for (int c = 0; c < _helds; c++) sum += _heldNormal[c];
            // One normal: the unit normals' sum is as long as their count (to float round-off).
            if (!(sum.Length() >= 0.999999f * springs)) return;
            Vector3 n = Vector3.Normalize(sum);
            float[] m = body.M;
            double mass = 0;
            Vector3 c0 = Vector3.Zero;
            for (int i = 0; i < _n; i++)
            {
                if (body.W[i] == 0f) return;
                mass += m[i];
                c0 += m[i] * x[i];
            }
            if (!(mass > 0)) return;
            Vector3 centre = c0 / (float)mass;
            double spin = 0, inertia = 0;
            for (int i = 0; i < _n; i++)
            {
                Vector3 r = x[i] - centre;
                spin += m[i] * Vector3.Dot(Vector3.Cross(r, x[i] - y[i]), n);
                inertia += m[i] * Vector3.Cross(r, n).LengthSquared();
            }
            if (!(inertia > 0)) return;
            double theta = -spin / inertia;
            if (!(Math.Abs(theta) > 0) || double.IsNaN(theta)) return;
            // Added as a move, x += sin(theta) n x r + (cos(theta) - 1) r_perp, not rebuilt as
            // c + R r: the rebuild rounds every coordinate to the float spacing of c, which moved
            // the ground springs' gaps by more than the few nm their load sits at.
            float sin = (float)Math.Sin(theta), cosMinusOne = (float)(-2 * Math.Sin(0.5 * theta) * Math.Sin(0.5 * theta));
            for (int i = 0; i < _n; i++)
            {
                Vector3 r = x[i] - centre;
                x[i] += sin * Vector3.Cross(n, r) + cosMinusOne * (r - Vector3.Dot(r, n) * n);
            }
        }

        // The momentum the dynamic bodies' shares took in the step goes to the bodies: each share
        // ended at x_i instead of its goal, a position impulse share (x_i - goal) at its contact
        // point. Only its pushing part along the normal is applied, and across the normal at most
        // mu times that (Coulomb). Summed per body and applied once: one by one in vertex order,
        // the first pushes would turn the body before the others are applied.
        void PushBodies(SoftBody body, Vector3[] x, float h, RigidCoupling coupling)
        {
            for (int c = 0; c < _contacts; c++)
            {
                int owner = _contactOwner[c];
                if (owner < 0) continue;
                Vector3 linear = Vector3.Zero, angular = Vector3.Zero;
                for (int d = c; d < _contacts; d++)
                {
                    if (_contactOwner[d] != owner) continue;
                    Vector3 n = _contactNormal[d];
                    Vector3 moved = (float)_contactMass[d] * (x[_contactVertex[d]] - _contactGoal[d]);
                    float push = -Vector3.Dot(moved, n);
                    if (push > 0f)
                    {
                        Vector3 across = moved + push * n;
                        float most = _contactFriction[d] * push, length = across.Length();
                        if (length > most) across *= most / length;
                        Vector3 impulse = across - push * n;
                        coupling.Accumulate(owner, _contactPoint[d], impulse, ref linear, ref angular);
                    }
                    body.Contacts.MetByNewton(_contactVertex[d], owner);
                    if (d > c) _contactOwner[d] = -1;
                }
                coupling.PushSum(owner, linear, angular, h);
            }
        }

        // G(x) without damping: inertia plus elastic energy (+infinity once a classic tet inverts).
        double Energy(SoftBody body, Vector3[] x, Vector3[] y, double invH2)
        {
            double e = 0;
            float[] m = body.M;
            for (int i = 0; i < _n; i++) e += 0.5 * m[i] * invH2 * (x[i] - y[i]).LengthSquared();
            for (int c = 0; c < _contacts; c++) e += 0.5 * _contactMass[c] * invH2 * (x[_contactVertex[c]] - _contactGoal[c]).LengthSquared();
            for (int c = 0; c < _overlaps; c++)
            {
                double gap = Vector3.Dot(x[_overlapVertex[c]] - _overlapPoint[c], _overlapNormal[c]);
                if (gap < 0) e += 0.5 * _overlapStiffness[c] * gap * gap;
            }
            if (_softTerms > 0) e += SoftContactEnergy(x);
            if (_sticks > 0) e += StickEnergy(x);
            Span<double> f = stackalloc double[9];
            foreach (TetElement t in body.Tets)
            {
                Mat3 g = DeformationGradient.Of(x[t.A], x[t.B], x[t.C], x[t.D], t.RestInverse);
                f[0] = g.C0.X; f[1] = g.C1.X; f[2] = g.C2.X;
                f[3] = g.C0.Y; f[4] = g.C1.Y; f[5] = g.C2.Y;
                f[6] = g.C0.Z; f[7] = g.C1.Z; f[8] = g.C2.Z;
                e += t.RestVolume * _tangent.Psi(f);
            }
            return e;
        }

        static void Set(Span<double> rest, int a, Vector3 r)
        {
            rest[3 * a] = r.X;
            rest[3 * a + 1] = r.Y;
            rest[3 * a + 2] = r.Z;
        }

        static double Component(Vector3 v, int i) => i == 0 ? v.X : i == 1 ? v.Y : v.Z;

        void Pin(int dof)
        {
            for (int col = Math.Max(0, dof - _band); col < dof; col++) At(dof, col) = 0;
            for (int row = dof + 1; row <= Math.Min(_dofs - 1, dof + _band); row++) At(row, dof) = 0;
            At(dof, dof) = 1;
            _rhs[dof] = 0;
        }

        // Band Cholesky in place (lower triangle); on a non-positive pivot the diagonal is shifted
        // (Levenberg: 1e-10 of the largest diagonal, x4 per retry, at most MaxShifts times) and
        // the factorisation restarts (Step then assembles again with definite element tangents
        // and factors that; _shifted says whether a shift was needed). False when the matrix has no finite positive diagonal or
        // is still not factored after the last shift (a non-finite entry): the step is skipped.
        // Before, the retries were unbounded, and a matrix with a NaN (or a zero diagonal, which
        // made every shift zero) hung the step for good (soft fuzz seed 3: a Newton beam at
        // E 1e9 Pa, nu 0.4999).
        bool Factor()
        {
            _shifted = false;
            Array.Copy(_matrix, _saved, _matrix.Length);
            double largest = 0;
            for (int i = 0; i < _dofs; i++) largest = Math.Max(largest, At(i, i));
            if (!(largest > 0) || double.IsInfinity(largest)) return false;
            double shift = 0;
            for (int tries = 0; !TryFactor(); tries++)
            {
                if (tries == MaxShifts) return false;
                shift = shift == 0 ? 1e-10 * largest : 4 * shift;
                _shifted = true;
                Array.Copy(_saved, _matrix, _matrix.Length);
                for (int i = 0; i < _dofs; i++) At(i, i) += shift;
            }
            return true;
        }

        // 1e-10 x 4^30 is 1e8 times the largest diagonal: the step is then a gradient step of
        // that length scale, and a matrix that still fails has a non-finite entry.
        const int MaxShifts = 30;

        bool TryFactor()
        {
            for (int k = 0; k < _dofs; k++)
            {
                int first = Math.Max(0, k - _band);
                double d = At(k, k);
                for (int s = first; s < k; s++) d -= At(k, s) * At(k, s);
                if (!(d > 0)) return false;
                d = Math.Sqrt(d);
                At(k, k) = d;
                int last = Math.Min(_dofs - 1, k + _band);
                for (int i = k + 1; i <= last; i++)
                {
                    double value = At(i, k);
                    for (int s = Math.Max(first, i - _band); s < k; s++) value -= At(i, s) * At(k, s);
                    At(i, k) = value / d;
                }
            }
            return true;
        }

        // Solves L L^T z = v in place for the vector v[offset .. offset + dofs).
        void Solve(double[] v, int offset)
        {
            for (int i = 0; i < _dofs; i++)
            {
                double value = v[offset + i];
                for (int s = Math.Max(0, i - _band); s < i; s++) value -= At(i, s) * v[offset + s];
                v[offset + i] = value / At(i, i);
            }
            for (int i = _dofs - 1; i >= 0; i--)
            {
                double value = v[offset + i];
                for (int s = i + 1; s <= Math.Min(_dofs - 1, i + _band); s++) value -= At(s, i) * v[offset + s];
                v[offset + i] = value / At(i, i);
            }
        }

        /// <summary>
        /// Reverse Cuthill-McKee numbering of the vertex graph (vertices sharing a tet are
        /// neighbours): breadth-first from a low-degree vertex, neighbours by increasing degree,
        /// reversed. It keeps the band of a mesh to about its smallest cross-section.
        /// </summary>
        static int[] ReverseCuthillMcKee(TetElement[] tets, int n)
        {
            var degree = new int[n];
            foreach (TetElement t in tets) { degree[t.A] += 3; degree[t.B] += 3; degree[t.C] += 3; degree[t.D] += 3; }
            var start = new int[n + 1];
            for (int i = 0; i < n; i++) start[i + 1] = start[i] + degree[i];
            var neighbours = new int[start[n]];
            var fill = new int[n];
            foreach (TetElement t in tets)
            {
                int[] q = { t.A, t.B, t.C, t.D };
                foreach (int a in q)
                    foreach (int b in q)
                        if (a != b) neighbours[start[a] + fill[a]++] = b;
            }
            var sequence = new int[n];
            var seen = new bool[n];
            int count = 0;
            while (count < n)
            {
                int root = -1;
                for (int i = 0; i < n; i++)
                    if (!seen[i] && (root < 0 || degree[i] < degree[root])) root = i;
                seen[root] = true;
                sequence[count++] = root;
                for (int head = count - 1; head < count; head++)
                {
                    int u = sequence[head];
                    int from = count;
                    for (int k = start[u]; k < start[u + 1]; k++)
                    {
                        int nb = neighbours[k];
                        if (seen[nb]) continue;
                        seen[nb] = true;
                        sequence[count++] = nb;
                    }
                    Array.Sort(sequence, from, count - from, new DegreeOrder(degree));
                }
            }
            var order = new int[n];
            for (int k = 0; k < n; k++) order[sequence[k]] = n - 1 - k;
            return order;
        }

        sealed class DegreeOrder : System.Collections.Generic.IComparer<int>
        {
            readonly int[] _degree;
            public DegreeOrder(int[] degree) => _degree = degree;
            public int Compare(int a, int b) => _degree[a] != _degree[b] ? _degree[a].CompareTo(_degree[b]) : a.CompareTo(b);
        }
    }
}
