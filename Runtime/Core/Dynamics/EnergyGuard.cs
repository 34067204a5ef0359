using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Keeps the constraint solve from creating kinetic energy. Passive constraints (contacts,
    /// joints without motors or springs, their limits and friction) can only redirect or remove
    /// kinetic energy: the exact velocity projection is dissipative. A Gauss-Seidel solve of
    /// joints that contradict each other is not: in 3D the bias of a persistent error leaks into
    /// the free directions as the bodies turn within the (sub)step (TGS), and redundant rows let
    /// warm-started impulses drift along directions whose effects cancel until the bodies turn
    /// (PGS). Both pumped bodies to hundreds of metres per second in the fuzzed worlds.
    /// <para>
    /// So each group of bodies connected through constraints (a solver island) is checked over
    /// the velocity solve: with v0 the velocities before it (gravity and forces already applied)
    /// and dv the change the constraints made, the kinetic energy K(s) = K(v0 + s dv) is
    /// quadratic in s. When K(1) exceeds K(0), the change is scaled by the largest s in [0, 1]
    /// with K(s) &lt;= K(0): s = -2 (v0 . M dv) / (dv . M dv). Scaling every constraint impulse of
    /// the island by the same factor keeps them equal and opposite (momentum is exchanged as
    /// before, only less of it) and leaves a solve that did not create energy untouched, so
    /// ordinary scenes step exactly as without the guard. A motor's work (its impulse times its
    /// target speed) is allowed for; islands with a spring or a kinematic body are skipped
    /// (those add energy by design), and so are islands without joints (contacts cannot
    /// contradict each other that way, and the unconverged rows under a heavy body resting on
    /// a light one keep a little energy that must not be taken from the heavy body's support).
    /// The slack (0.01 J per kg of the island and a relative 1e-5 per (sub)step) keeps the
    /// guard off the ordinary Gauss-Seidel error of chains holding heavy loads.
    /// </para>
    /// <para>
    /// Under TGS the window spans the position integration, which turns the bodies: a free
    /// body keeps its angular momentum, so its world angular velocity turns too. For a body
    /// that turned, the start velocity is carried as momentum, w0' = I1^-1 I0 w0 (I0, I1 its
    /// world inertia at the window's start and end), and the scaling is taken from there; if
    /// the island still ends above the energy it began with, its rotation is scaled down to it.
    /// </para>
    /// <para>
    /// Islands of contacts alone are checked over what follows the solve: TGS's relax passes
    /// and the restitution passes. Neither may leave an island more kinetic energy than it had
    /// at the start of the (sub)step, or than the solve left it, whichever is more (a relax
    /// pass only removes the bias's velocity; a bounce, e &lt;= 1, gives back at most the
    /// approach's energy); beyond that their own velocity change is scaled back, so the solve's
    /// support of a heavy body is untouched. Both work on the contact geometry of the step's
    /// start, and a compound of three offset shapes turning 1.9 rad in a one-substep step was
    /// spun from 113 to 483 rad/s by the relax passes (WorldFuzz seed 1547).
    /// </para>
    /// </summary>
    internal sealed class EnergyGuard
    {
        // Relative and absolute slack (J per kg) before the guard acts: rounding in a solve that
        // did not really create energy must not change the motion.
        const float RelativeSlack = 1e-5f;
        const float SlackPerKilogram = 1e-2f;

        // Turn per step (rad) above which a step's contact-only islands are checked after the solve.
        const float FastTurn = 0.5f;

        int[] _parent = new int[16];
        bool[] _exempt = new bool[16];
        bool[] _jointed = new bool[16];
        Vector3[] _linear = new Vector3[16];
        Vector3[] _angular = new Vector3[16];
        // Velocities after the solve (before the relax and restitution passes).
        Vector3[] _solvedLinear = new Vector3[16];
        Vector3[] _solvedAngular = new Vector3[16];
        bool _anyAfterSolve;
        Mat3[] _inertia = new Mat3[16];
        // Each body's world inverse inertia at Begin: TGS turns the bodies (and their world
        // inertia) inside the window, and the guard must tell that turn from the constraints' change.
        Mat3[] _beginInverse = new Mat3[16];
        // Per island root: twice the kinetic energy at Begin (with the inertia of then), the
        // factor on the rotation where a turn raised it, and whether a body turned.
        double[] _begin = new double[16];
        // Per island root: the rotational parts of _k00, _k01, _k11.
        double[] _a00 = new double[16], _a01 = new double[16], _a11 = new double[16];
        float[] _factor = new float[16];
        bool[] _turned = new bool[16];
        // Per island root: sums of v0.M.v0, v0.M.dv, dv.M.dv and the mass.
        double[] _k00 = new double[16], _k01 = new double[16], _k11 = new double[16], _mass = new double[16], _work = new double[16];
        float[] _scale = new float[16];
        int _count;
        bool _any;

        /// <summary>Number of times the guard scaled an island's constraint impulses since the world was created.</summary>
        public long Activations;

        /// <summary>
        /// Groups the solver's bodies into islands through the prepared contacts and joints and
        /// marks the islands that may gain energy by design. Call after <see cref="SolverContext.Prepare"/>.
        /// </summary>
        public void Build(SolverContext c, IslandBuilder islands, ContactManifold[] manifolds, JointStorage joints)
        {
            int n = c.BodyCount;
            _count = n;
            _any = false;
            _anyAfterSolve = false;
            // Contact-only islands are left alone by the velocity-solve check (below). They are
            // checked after the solve only where that can go wrong: in a
            // step with restitution, or with a body turning more than half a radian (the relax
            // passes work on the step's start geometry). A cheap look at the bodies decides.
            bool fastTurn = false;
            float turn2 = FastTurn * FastTurn / (c.StepDt * c.StepDt);
            for (int k = 1; k < n && !fastTurn; k++) fastTurn = c.Bodies[k].AngularVelocity.LengthSquared() > turn2;
            bool afterSolve = c.HasRestitution || fastTurn;
            if (islands.JointCount == 0 && !afterSolve) return;
            if (_parent.Length < n) Reserve(Math.Max(16, 2 * n));
            for (int k = 0; k < n; k++)
            {
                _parent[k] = k;
                _exempt[k] = false;
                _jointed[k] = false;
            }
            for (int i = 0; i < islands.ManifoldCount; i++)
            {
                ref ContactManifold m = ref manifolds[islands.Manifolds[i]];
                Join(c, c.IndexOf(m.BodyA), c.IndexOf(m.BodyB), false);
            }
            for (int i = 0; i < islands.JointCount; i++)
            {
                ref JointData j = ref joints.Data[islands.Joints[i]];
                bool active = j.SpringHertz > 0;
                int a = c.IndexOf(j.BodyA), b = c.IndexOf(j.BodyB);
                Join(c, a, b, active);
                _jointed[a] = _jointed[b] = true;
            }
            // Flags live on the roots. Islands without joints are left alone: contacts cannot
            // contradict each other the way joints do, and a heavy body resting on a light one
            // leaves the light one's unconverged rows a little energy that must not be taken
            // out of the heavy one's support.
            for (int k = 1; k < n; k++)
            {
                if (_exempt[k]) _exempt[Find(k)] = true;
                if (_jointed[k]) _jointed[Find(k)] = true;
            }
            for (int k = 1; k < n; k++)
            {
                ref SolverBody b = ref c.Bodies[k];
                if (b.IsDynamic == 0) continue;
                // Locked rotation axes make the projected inverse singular: the energy lives on
                // the free axes, where the pseudo-inverse is the inertia the solver works with.
                _inertia[k] = (b.Locks & AxisLocks.Angular) != 0 ? AxisLockMath.InverseOnFreeAxes(b.InverseInertia) : b.InverseInertia.Inverse();
                int r = Find(k);
                if (_exempt[r]) continue;
                if (_jointed[r]) _any = true;
                else if (afterSolve) _anyAfterSolve = true;
            }
        }

        /// <summary>Sizes the per-body arrays for <paramref name="bodies"/> solver bodies, so steps within that count allocate nothing.</summary>
        public void Reserve(int bodies)
        {
            if (_parent.Length >= bodies) return;
            _parent = new int[bodies];
            _exempt = new bool[bodies];
            _jointed = new bool[bodies];
            _linear = new Vector3[bodies];
            _angular = new Vector3[bodies];
            _solvedLinear = new Vector3[bodies];
            _solvedAngular = new Vector3[bodies];
            _inertia = new Mat3[bodies];
            _beginInverse = new Mat3[bodies];
            _begin = new double[bodies];
            _a00 = new double[bodies];
            _a01 = new double[bodies];
            _a11 = new double[bodies];
            _factor = new float[bodies];
            _turned = new bool[bodies];
            _k00 = new double[bodies];
            _k01 = new double[bodies];
            _k11 = new double[bodies];
            _mass = new double[bodies];
            _work = new double[bodies];
            _scale = new float[bodies];
        }

        /// <summary>Records the velocities before the velocity solve.</summary>
        /// <remarks>Motors are not exempt: their work this (sub)step, at most |impulse| x |target speed|, is added to the island's allowance in <see cref="End"/>.</remarks>
        public void Begin(SolverContext c)
        {
            if (!_any && !_anyAfterSolve) return;
            SolverBody[] bodies = c.Bodies;
            for (int k = 1; k < _count; k++)
            {
                _linear[k] = bodies[k].LinearVelocity;
                _angular[k] = bodies[k].AngularVelocity;
                _beginInverse[k] = bodies[k].InverseInertia;
            }
        }

        /// <summary>
        /// Scales the velocity change of every island whose kinetic energy the solve raised, so
        /// that it ends no higher than it began.
        /// </summary>
        public void End(SolverContext c, IslandBuilder islands, JointStorage joints)
        {
            if (!_any) return;
            SolverBody[] bodies = c.Bodies;
            for (int k = 1; k < _count; k++)
            {
                _k00[k] = _k01[k] = _k11[k] = _mass[k] = _work[k] = _begin[k] = _a00[k] = _a01[k] = _a11[k] = 0;
                _scale[k] = _factor[k] = 1f;
                _turned[k] = false;
            }
            // A motor may add at most its impulse times its target speed (it pushes towards
            // that speed and brakes beyond it).
            for (int i = 0; i < islands.JointCount; i++)
            {
                ref JointData j = ref joints.Data[islands.Joints[i]];
                if (j.MaxMotorForce <= 0) continue;
                float impulse = j.Kind == JointKind.Hinge ? j.Parts.Hinge.Motor.Impulse
                              : j.Kind == JointKind.Prismatic ? j.Parts.Prismatic.Motor.Impulse : 0f;
                int a = c.IndexOf(j.BodyA), b = c.IndexOf(j.BodyB);
                int r = Find(a != 0 ? a : b);
                if (r != 0) _work[r] += Math.Abs(impulse) * Math.Abs(j.MotorSpeed);
            }
            for (int k = 1; k < _count; k++)
            {
                ref SolverBody b = ref bodies[k];
                if (b.IsDynamic == 0) continue;
                int r = Find(k);
                if (_exempt[r] || !_jointed[r]) continue;
                float m = 1f / b.InverseMass;
                Vector3 v0 = _linear[k], w0 = _angular[k];
                Mat3 inertia = _inertia[k];
                Mat3 now = b.InverseInertia, then = _beginInverse[k];
                double begin = m * Vector3.Dot(v0, v0) + Vector3.Dot(w0, inertia * w0);
                if (now.C0 != then.C0 || now.C1 != then.C1 || now.C2 != then.C2)
                {
                    // The body turned in the window (TGS's position integration), and its world
                    // angular velocity with it: a free body keeps its angular momentum L, not its
                    // angular velocity. The constraints' change is measured (and scaled) from the
                    // start momentum in the turned body, w0' = I1^-1 I0 w0, with the end inertia
                    // I1. Taken back toward w0 itself in its turned pose, a 2.7 t rod spinning
                    // about its long axis had the spin moved onto its heavy axes, 2.3 to 16 MJ in
                    // three steps (WorldFuzz seed 1388).
                    inertia = Inertia(b, now);
                    Vector3 momentum = Inertia(b, then) * w0;
                    begin = m * Vector3.Dot(v0, v0) + Vector3.Dot(w0, momentum);
                    w0 = now * momentum;
                    _angular[k] = w0;
                    _turned[r] = true;
                }
                Vector3 dv = b.LinearVelocity - v0, dw = b.AngularVelocity - w0;
                Vector3 iw0 = inertia * w0, idw = inertia * dw;
                _k00[r] += m * Vector3.Dot(v0, v0) + Vector3.Dot(w0, iw0);
                _k01[r] += m * Vector3.Dot(v0, dv) + Vector3.Dot(w0, idw);
                _k11[r] += m * Vector3.Dot(dv, dv) + Vector3.Dot(dw, idw);
                _begin[r] += begin;
                _a00[r] += Vector3.Dot(w0, iw0);
                _a01[r] += Vector3.Dot(w0, idw);
                _a11[r] += Vector3.Dot(dw, idw);
                _mass[r] += m;
            }
            bool scaled = false;
            for (int r = 1; r < _count; r++)
            {
                if (_parent[r] != r || _exempt[r] || !_jointed[r] || _k11[r] <= 0) continue;
                // 2 K(1) - 2 K(Begin) = 2 v0.M.dv + dv.M.dv, plus K(0) - K(Begin) where a body turned.
                double offset = _turned[r] ? _k00[r] - _begin[r] : 0;
                double rise = offset + 2 * _k01[r] + _k11[r];
                double slack = RelativeSlack * _k00[r] + SlackPerKilogram * _mass[r] + _work[r];
                if (!(rise > 2 * slack)) continue; // also skips a NaN sum (a singular inertia)
                // Largest s with 2 s v0.M.dv + s^2 dv.M.dv <= 0 (0 when the change only adds).
                double s = -2 * _k01[r] / _k11[r];
                if (!(s > 0)) s = 0;
                s = Math.Min(1, s);
                if (_turned[r])
                {
                    // Even at K(0) a turned island may hold more than it began with: its bodies
                    // turned, under the solve's velocities, into a pose in which their start
                    // momentum carries more energy. Then the rotation comes down to what the
                    // island began with; the linear motion stays as scaled. Without this the
                    // rod of seed 928 (5.4 t, held by contradictory joints to a 5 kg body) went
                    // from 0.15 to 0.68 MJ in 12 steps with every solve scaled.
                    double end = _k00[r] + 2 * s * _k01[r] + s * s * _k11[r];
                    double angular = _a00[r] + 2 * s * _a01[r] + s * s * _a11[r];
                    double room = _begin[r] + 2 * slack - (end - angular);
                    if (end > _begin[r] + 2 * slack && angular > 0)
                        _factor[r] = (float)Math.Sqrt(Math.Max(0, Math.Min(1, room / angular)));
                }
                _scale[r] = (float)s;
                scaled = true;
                Activations++;
            }
            if (scaled) Rescale(bodies, _linear, _angular);
        }

        /// <summary>Records the velocities after the solve, before the relax and restitution passes (contact-only islands; jointed ones are in <see cref="End"/>'s window).</summary>
        public void BeginAfterSolve(SolverContext c)
        {
            if (!_anyAfterSolve) return;
            SolverBody[] bodies = c.Bodies;
            for (int k = 1; k < _count; k++)
            {
                _solvedLinear[k] = bodies[k].LinearVelocity;
                _solvedAngular[k] = bodies[k].AngularVelocity;
            }
        }

        /// <summary>
        /// Scales back the relax and restitution passes' velocity change in each contact-only
        /// island that ends with more kinetic energy than it had at <see cref="Begin"/> and than
        /// the solve left it (see the class remarks).
        /// </summary>
        public void EndAfterSolve(SolverContext c)
        {
            if (!_anyAfterSolve) return;
            SolverBody[] bodies = c.Bodies;
            // Per root, all as 2K: _k00 at Begin, _k01 after the solve, _work v_r.M.dv, _k11 dv.M.dv.
            for (int k = 1; k < _count; k++)
            {
                _k00[k] = _k01[k] = _k11[k] = _mass[k] = _work[k] = 0;
                _scale[k] = _factor[k] = 1f;
            }
            bool any = false;
            for (int k = 1; k < _count; k++)
            {
                ref SolverBody b = ref bodies[k];
                if (b.IsDynamic == 0) continue;
                int r = Find(k);
                if (_exempt[r] || _jointed[r]) continue;
                float m = 1f / b.InverseMass;
                Vector3 v0 = _linear[k], w0 = _angular[k], vr = _solvedLinear[k], wr = _solvedAngular[k];
                Vector3 dv = b.LinearVelocity - vr, dw = b.AngularVelocity - wr;
                Mat3 inertia = _inertia[k];
                _k00[r] += m * Vector3.Dot(v0, v0) + Vector3.Dot(w0, inertia * w0);
                _k01[r] += m * Vector3.Dot(vr, vr) + Vector3.Dot(wr, inertia * wr);
                _work[r] += m * Vector3.Dot(vr, dv) + Vector3.Dot(wr, inertia * dw);
                _k11[r] += m * Vector3.Dot(dv, dv) + Vector3.Dot(dw, inertia * dw);
                _mass[r] += m;
                any |= dv != Vector3.Zero || dw != Vector3.Zero;
            }
            if (!any) return;
            bool scaled = false;
            for (int r = 1; r < _count; r++)
            {
                if (_parent[r] != r || _exempt[r] || _jointed[r] || _k11[r] <= 0) continue;
                // 2K(s) = k01 + 2 s work + s^2 k11 may not pass twice the larger of the energy at
                // Begin (with slack) and after the solve.
                double bound = Math.Max(_k00[r] * (1 + 2 * RelativeSlack) + 2 * SlackPerKilogram * _mass[r], _k01[r]);
                double end = _k01[r] + 2 * _work[r] + _k11[r];
                if (!(end > bound)) continue; // also skips a NaN sum
                // Largest s in [0, 1] with k11 s^2 + 2 work s + (k01 - bound) <= 0.
                double a = _k11[r], half = _work[r], rest = _k01[r] - bound;
                double disc = half * half - a * rest;
                double s = disc > 0 ? (-half + Math.Sqrt(disc)) / a : 0;
                _scale[r] = (float)Math.Max(0, Math.Min(1, s));
                scaled = true;
                Activations++;
            }
            if (scaled) Rescale(bodies, _solvedLinear, _solvedAngular);
        }

        // Takes every dynamic body of a scaled island back toward the recorded velocities by its
        // island's factor: v = v0 + s (v - v0). Islands left alone have s = 1 and are untouched.
        void Rescale(SolverBody[] bodies, Vector3[] linear, Vector3[] angular)
        {
            for (int k = 1; k < _count; k++)
            {
                ref SolverBody b = ref bodies[k];
                if (b.IsDynamic == 0) continue;
                int r = Find(k);
                float s = _scale[r], f = _factor[r];
                if (s == 1f && f == 1f) continue;
                b.LinearVelocity = linear[k] + s * (b.LinearVelocity - linear[k]);
                b.AngularVelocity = angular[k] + s * (b.AngularVelocity - angular[k]);
                if (f != 1f) b.AngularVelocity *= f;
            }
        }

        // A body's world inertia from its world inverse inertia (on the free axes where rotation
        // is locked: the pseudo-inverse the solver works with).
        static Mat3 Inertia(in SolverBody b, in Mat3 inverse) =>
            (b.Locks & AxisLocks.Angular) != 0 ? AxisLockMath.InverseOnFreeAxes(inverse) : inverse.Inverse();

        void Join(SolverContext c, int a, int b, bool active)
        {
            // Index 0 (static bodies) joins nothing; a kinematic body (non-dynamic, own index)
            // drives its island, so the island is exempt.
            bool kinematicA = a != 0 && c.Bodies[a].IsDynamic == 0;
            bool kinematicB = b != 0 && c.Bodies[b].IsDynamic == 0;
            if (active || kinematicA || kinematicB)
            {
                if (a != 0) _exempt[a] = true;
                if (b != 0) _exempt[b] = true;
            }
            if (a == 0 || b == 0) return;
            int ra = Find(a), rb = Find(b);
            if (ra == rb) return;
            if (ra < rb) _parent[rb] = ra;
            else _parent[ra] = rb;
            if (_exempt[ra] || _exempt[rb]) _exempt[ra] = _exempt[rb] = true;
        }

        int Find(int k)
        {
            while (_parent[k] != k)
            {
                _parent[k] = _parent[_parent[k]];
                k = _parent[k];
            }
            return k;
        }
    }
}
