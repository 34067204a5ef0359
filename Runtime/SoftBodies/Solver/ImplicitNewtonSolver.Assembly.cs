using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Assembles G's gradient and Hessian: inertia, each element's tangent (exact, or made
    /// definite), damping, the contact and attachment springs, and the Dirichlet rows of held
    /// vertices.
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
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
    }
}
