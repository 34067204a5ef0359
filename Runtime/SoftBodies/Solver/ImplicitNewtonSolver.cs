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
            BeginAttachments(body, x, y, invH2, coupling);
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
            if (_bodyCount > 0 && !SolveBodies(body))
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
                    if (_partnerCount > 0) MovePartners(body, (float)step, h);
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
    }
}
