using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// After the step: what the contacts' springs carried handed to the shapes and bodies (support,
    /// momentum, the spin about a flat contact).
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
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
    }
}
