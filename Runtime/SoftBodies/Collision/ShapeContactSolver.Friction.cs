using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Coulomb friction of the contacts, patch by patch: a resting patch held as one, a sliding one
    /// braked with the cone of all its vertices.
    /// </summary>
    internal sealed partial class ShapeContactSolver
    {
        /// <summary>Adds the friction's moves of the substep to the velocities (Newton bodies; see _frictionMove).</summary>
        public void ApplyFrictionVelocities(Vector3[] v, float[] w, float invH)
        {
            int n = Math.Min(v.Length, _frictionMove.Length);
            for (int i = 0; i < n; i++)
                if (w[i] != 0f) v[i] += _frictionMove[i] * invH;
        }

        /// <summary>How closely a patch's slips must point one way for it to be held as one: 0.8 (see <see cref="HoldPatch"/>).</summary>
        const float Coherent = 0.8f;

        /// <summary>How many times its own cone a vertex of a resting patch may be held by: 2 (1.5 and 3 measured the same).</summary>
        const float Borrow = 2f;

        /// <summary>How far past the collision radius, as a fraction of it, a Newton body's friction reaches: 0.01 (see Solve).</summary>
        const float FrictionSkin = 0.01f;

        /// <summary>The speed (m/s) below which every vertex of a body must be for its patches to hold as one: 0.1.</summary>
        const float RestingSpeed = 0.1f;

        /// <summary>Whether every free vertex of the body started the substep slower than <see cref="RestingSpeed"/>.</summary>
        static bool Still(SoftBody body, Vector3 gravityStep)
        {
            Vector3[] v = body.V;
            float[] free = body.FreeW;
            for (int i = 0; i < v.Length; i++)
                if (free[i] != 0f && (v[i] - gravityStep).LengthSquared() >= RestingSpeed * RestingSpeed) return false;
            return true;
        }

        // A patch vertex that touched the shape in the last substep too, or was within its reach
        // while the body rested (not one arriving now).
        bool Settled(int p) => _holdLast[_patchVertex[p]] || _restLast[_patchVertex[p]];

        // A vertex of the patch taken with the others (HoldPatch): every vertex within reach of a
        // body at rest (the ground springs hold its vertices at the collision radius, and which
        // of them the contact pass pushed changes from substep to substep while the body's whole
        // weight is on them), else those that settled (not one arriving now).
        bool Member(int p, bool still) => still || Settled(p);

        /// <summary>
        /// Friction of a Newton body against one immovable shape, over the patch of its vertices
        /// touching it. The vertices that touched it in the last substep too are taken together
        /// when their slips point one way (the length of their sum at least
        /// <see cref="Coherent"/> times the sum of their lengths), like a rigid solver's manifold
        /// friction, within the cone of them all (mu times the sum of their normal impulses less
        /// the friction they spent):
        /// - resting (the slips need no more than that cone, every vertex of the body slower than
        ///   <see cref="RestingSpeed"/>, <see cref="Still"/>, and at least half of the patch stuck
        ///   in the last substep): every vertex is held, each by at most <see cref="Borrow"/> times
        ///   its own cone;
        /// - otherwise each vertex is held within its own cone, and the cone the vertices held
        ///   whole leave unused goes to those that slip, the same share of each one's excess (at
        ///   most <see cref="Borrow"/> times its own cone while the patch as a whole could hold),
        ///   so a sliding patch brakes with the cone of them all.
        /// The vertices arriving now, and patches whose slips spread apart (a slab crushed by a
        /// crate: the ground under its middle cannot hold its edges), take each vertex within its
        /// own cone. Of a body at rest every vertex within reach is taken with the patch, the
        /// friction its Newton step's sticking springs took is first held to the patch's cone
        /// (<see cref="CapSticks"/>), and the vertices stick in the next step (<see cref="Sticks"/>).
        /// Per vertex, the normal impulses a Newton step's springs measure (<see cref="Support"/>)
        /// spread over a face unlike the pull along it: resting, the vertices short of load
        /// slipped every substep, downhill only (a cube on a 30 degree slope at mu 0.8 crept
        /// 1.4 cm/s; now at most 0.3 mm/s); sliding, the few vertices carrying a stiff body's load
        /// were held whole by their own cones and the rest of those cones went unused (a cube of
        /// E 1e8 Pa slid on at 10 cm/s down a 20 degree slope at mu 0.5, braking at 74 % of the
        /// cone; now 5.1 cm/s). The resting hold is not for a body in motion (soft fuzz seed 93,
        /// a 4.8 t body crushing a 3.8 kg box, diverged), for vertices arriving (a nu 0.49 cube
        /// thrown at 10 m/s: the vertices beside its struck corner were held by its cone, min J
        /// 0.21-0.31 against 0.69), nor with no bound per vertex (a stiff slab holding a landed
        /// 1 t crate blew apart in one step, put back). Sharing out the spare cone only once the
        /// patch slid as a whole braked a struck corner harder (a nu 0.4999 cube thrown down and
        /// across at 10 m/s: min J 0.46; 0.62 now, 0.59 with each vertex in its own cone).
        /// </summary>
        void HoldPatch(SoftBody body, int count, float mu, int owner, RigidCoupling coupling, float h, Vector3 gravityStep, bool still)
        {
            CapSticks(body, count, mu, still);
            double cone = 0, need = 0;
            Vector3 net = Vector3.Zero;
            int members = 0, stuck = 0;
            for (int p = 0; p < count; p++)
            {
                if (!Member(p, still)) continue;
                int i = _patchVertex[p];
                members++;
                cone += mu * (_pushed[i] + _support[i]) - _held[i];
                need += _patchSlip[p];
                net += _patchSlip[p] * _patchTangent[p];
                if (_stuckLast[i]) stuck++;
            }
            bool coherent = members > 0 && net.Length() >= Coherent * need;
            bool holds = need <= cone;
            bool pooled = coherent && holds && still && 2 * stuck >= members;
            bool spill = coherent && !pooled;
            float share = 0f, limit = 1f;
            if (spill)
            {
                double spare = 0, deficit = 0;
                for (int p = 0; p < count; p++)
                {
                    if (!Member(p, still)) continue;
                    int i = _patchVertex[p];
                    float own = MathF.Max(0f, mu * (_pushed[i] + _support[i]) - _held[i]);
                    spare += Math.Max(0, own - _patchSlip[p]);
                    deficit += Math.Max(0, _patchSlip[p] - own);
                }
                share = deficit > 0 ? (float)Math.Min(1, spare / deficit) : 0f;
                // What the shares take, within what is left of the patch's cone: a vertex that lent
                // its cone in an earlier pass still has it by its own measure, and the end-of-substep
                // pass gave it out again (Newton cubes at two and three iterations slid up to 46 %
                // slow). Only for a free body, whose weight the patch alone carries: with the limit
                // for pinned and attached bodies too, three soft fuzz worlds of such bodies
                // (seeds 53, 77, 229) failed newly; that case is open (CHANGELOG, Known limits).
                if (Unpinned(body))
                {
                    double taken = 0;
                    for (int p = 0; p < count; p++) if (Member(p, still)) taken += SpillTake(p, mu, share, holds);
                    if (taken > Math.Max(0, cone)) limit = (float)(Math.Max(0, cone) / taken);
                }
            }
            for (int p = 0; p < count; p++)
            {
                int i = _patchVertex[p];
                float slip = _patchSlip[p], own = mu * (_pushed[i] + _support[i]) - _held[i], dlt;
                if (spill && Member(p, still))
                {
                    dlt = limit * SpillTake(p, mu, share, holds);
                    if (slip <= MathF.Max(0f, own) && slip > 0f && limit == 1f) _stuckNow[i] = true;
                }
                else if (pooled && Member(p, still))
                {
                    float most = Borrow * MathF.Max(0f, own);
                    dlt = MathF.Min(slip, most);
                    if (slip <= most) _stuckNow[i] = true;
                }
                else
                {
                    if (slip == 0f) continue;
                    dlt = slip;
                    if (dlt > own) dlt = MathF.Max(0f, own);
                    else _stuckNow[i] = true;
                }
                Slide(body, i, owner, _patchContact[p], _patchTangent[p], dlt, coupling, h, gravityStep);
            }
            // A body at rest on the shape sticks to it in the next substep's Newton step (Sticks).
            if (!still || !Unpinned(body)) return;
            for (int p = 0; p < count; p++)
            {
                int i = _patchVertex[p];
                _restNow[i] = true;
                _restVelocityNow[i] = coupling.PointVelocity(owner, _patchContact[p]);
                _restNormalNow[i] = _patchNormal[p];
            }
        }

        // The correction a member of a spilling patch takes (HoldPatch): its own slip within its own
        // cone, and the given share of the excess beyond it (at most Borrow times the cone while the
        // patch as a whole could hold).
        float SpillTake(int p, float mu, float share, bool holds)
        {
            int i = _patchVertex[p];
            float slip = _patchSlip[p], cap = MathF.Max(0f, mu * (_pushed[i] + _support[i]) - _held[i]);
            float dlt = slip <= cap ? slip : cap + share * (slip - cap);
            return holds ? MathF.Min(dlt, Borrow * cap) : dlt;
        }

        /// <summary>
        /// The friction the Newton step's sticking springs took at this patch (<see cref="Sticks"/>,
        /// reported by <see cref="Stuck"/>), as one force like a rigid solver's manifold friction,
        /// within the patch's cone: beyond it the whole body slides on by the excess, spread over
        /// its mass (Coulomb's kinetic friction), and the cone it used is spent.
        /// </summary>
        void CapSticks(SoftBody body, int count, float mu, bool still)
        {
            Vector3 sticks = Vector3.Zero;
            for (int p = 0; p < count; p++) if (Member(p, still)) sticks += _stick[_patchVertex[p]];
            if (sticks == Vector3.Zero) return;
            // A later iteration's step holds the body from the substep's start again, and its
            // report replaces the last: the cone an earlier one spent is given back first.
            double cone = 0;
            for (int p = 0; p < count; p++)
            {
                if (!Member(p, still)) continue;
                int i = _patchVertex[p];
                _held[i] -= _stickHeld[i];
                _stickHeld[i] = 0f;
                cone += MathF.Max(0f, mu * (_pushed[i] + _support[i]) - _held[i]);
            }
            float taken = sticks.Length();
            if (taken > cone)
            {
                Vector3 excess = (float)((taken - cone) / taken) * sticks;
                Vector3[] x = body.X;
                float[] m = body.M, free = body.FreeW;
                double mass = 0;
                for (int i = 0; i < x.Length; i++) if (free[i] != 0f) mass += m[i];
                if (mass > 0)
                {
                    Vector3 d = excess / (float)mass;
                    for (int i = 0; i < x.Length; i++) if (free[i] != 0f) x[i] += d;
                }
            }
            float used = cone > 0 ? (float)Math.Min(1.0, taken / cone) : 0f;
            for (int p = 0; p < count; p++)
            {
                if (!Member(p, still)) continue;
                int i = _patchVertex[p];
                _stickHeld[i] = used * MathF.Max(0f, mu * (_pushed[i] + _support[i]) - _held[i]);
                _held[i] += _stickHeld[i];
                _stick[i] = Vector3.Zero;
            }
        }

        // Whether every vertex of the body is free (nothing pinned or attached): only such a body
        // sticks as a whole and slides on by a uniform move (CapSticks).
        static bool Unpinned(SoftBody body)
        {
            float[] free = body.FreeW;
            for (int i = 0; i < free.Length; i++) if (free[i] == 0f) return false;
            return true;
        }

        // Friction's correction dlt (kg m) at vertex i along -t, counted against the cone. For a
        // Newton body, the slip the vertex brought in with its velocity (all of it unless static
        // friction held the vertex in the last substep too) is taken out of the velocity and
        // left to the next implicit step; only what the substep's own forces added to a resting
        // contact (gravity along a slope, the elastic pull) comes out of the position. Taken out
        // of the position alone, friction braking a struck corner sheared it (a cube at nu 0.4999
        // thrown down and across at 10 m/s: min J 0.15) and stored strain the motion did not hold
        // (a Newton beam landing gained energy, soft fuzz seed 12); out of the velocity alone, a
        // body resting on a slope crept 7 cm/s.
        void Slide(SoftBody body, int i, int owner, Vector3 contact, Vector3 t, float dlt, RigidCoupling coupling, float h, Vector3 gravityStep)
        {
            float wi = body.W[i];
            _held[i] += dlt;
            if (body.Solver == SoftSolver.Newton)
            {
                Vector3 incoming = (body.V[i] - gravityStep - coupling.PointVelocity(owner, contact)) * h;
                float carried = _stuckLast[i] ? MathF.Min(wi * dlt, MathF.Max(0f, Vector3.Dot(incoming, t))) : wi * dlt;
                _frictionMove[i] -= carried * t;
                body.X[i] -= (wi * dlt - carried) * t;
            }
            else body.X[i] -= wi * dlt * t;
            coupling.Push(owner, contact, dlt * t, h);
        }
    }
}
