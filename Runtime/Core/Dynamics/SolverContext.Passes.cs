using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    internal sealed partial class SolverContext
    {
        void RunJoint(ref JointData j, JointSolver.Pass pass)
        {
            SolverBody a = Bodies[j.SolverA];
            SolverBody b = Bodies[j.SolverB];
            JointSolver.Run(ref j, ref a, ref b, pass, _jointParameters);
            if (a.IsDynamic != 0) Bodies[j.SolverA] = a;
            if (b.IsDynamic != 0) Bodies[j.SolverB] = b;
        }

        // ---- passes ---------------------------------------------------------------------

        /// <summary>v += h (g + F/m), w += h I^-1 tau for the dynamic solver bodies (TGS substeps).</summary>
        public void IntegrateVelocities()
        {
            _bodyJob.Positions = false;
            if (Pool != null) Pool.For(_bodyJob, 1, BodyCount, 4 * MinChunk);
            else _bodyJob.Execute(1, BodyCount);
        }

        /// <summary>Levels the step's bodies and collects the contacts between levels for <see cref="Shock"/>.</summary>
        public void PrepareShock(IslandBuilder islands) =>
            _shock.Build(Bodies, BodyCount, _manifolds, islands.Manifolds, islands.ManifoldCount, _indexOfSlot, _settings.LinearSlop, _settings.ShockDepth, _dt);

        /// <summary>
        /// The shock-propagation sweep of the substep (see <see cref="ShockPropagation"/>), or one
        /// of PGS's two (<paramref name="pass"/>; in the second a pressed contact's friction is for
        /// at least the upper body's weight, see ShockPropagation.SweepManifold).
        /// </summary>
        public void Shock(SweepPass pass = SweepPass.Whole)
        {
            Vector3 g = _settings.Gravity;
            float length = g.Length();
            _shock.Sweep(Bodies, _settings.ShockDepth, length > 0 ? -g / length : Vector3.Zero, _h, _settings.MaxContactPushSpeed, length, pass, Pool);
        }

        /// <summary>
        /// dp += v h and dq = exp(w h) dq for every moving solver body (TGS substeps); a dynamic
        /// body whose principal moments differ turns as a free body does
        /// (<see cref="Integrator.RotateFreeBody"/>), so that its angular momentum, not its
        /// angular velocity, is what carries over between constraint impulses (the gyroscopic
        /// terms).
        /// </summary>
        public void IntegratePositions()
        {
            // The joint trees' factorisation follows the arms and world inertias: once per
            // position update (and once at the start of the step), for the relax pass and the
            // next substep's biased passes alike.
            _trees.Invalidate();
            _bodyJob.Positions = true;
            if (Pool != null) Pool.For(_bodyJob, 1, BodyCount, 4 * MinChunk);
            else _bodyJob.Execute(1, BodyCount);
        }

        /// <summary>Velocity or position integration of the solver bodies [start, end).</summary>
        sealed class BodyJob : IParallelJob
        {
            readonly SolverContext _c;
            public bool Positions;

            public BodyJob(SolverContext context) => _c = context;

            public void Execute(int start, int end)
            {
                SolverContext c = _c;
                SolverBody[] bodies = c.Bodies;
                SubstepKick[] kicks = c._kick;
                BodyStorage s = c._storage;
                if (Positions)
                {
                    float h = c._h;
                    float speedCap = c._settings.MaxLinearSpeed;
                    for (int k = start; k < end; k++)
                    {
                        ref SolverBody body = ref bodies[k];
                        ref SubstepKick kick = ref kicks[k];
                        // The cap holds for what the constraints added too: a light body jointed
                        // to a heavy one in a contradictory pose was flung at 1e5 m/s (WorldFuzz).
                        if (body.IsDynamic != 0) Integrator.ClampSpeed(speedCap, kick.Radius, ref body.LinearVelocity, ref body.AngularVelocity);
                        body.DeltaPosition += h * body.LinearVelocity;
                        if (body.AngularVelocity == Vector3.Zero) continue;
                        if (body.IsDynamic == 0 || kick.Isotropic)
                        {
                            body.DeltaRotation = Rotation.Integrate(body.DeltaRotation, body.AngularVelocity, h);
                            continue;
                        }
                        int slot = c.BodySlot[k];
                        Vector3 ii = s.InverseInertiaPrincipal[slot];
                        AxisLocks locks = body.Locks & AxisLocks.Angular;
                        if (locks != 0)
                        {
                            // Locked rotation axes: no free-body splitting (it would turn the
                            // momentum onto the locked axes); the projected inertia follows the turn.
                            body.DeltaRotation = Rotation.Integrate(body.DeltaRotation, body.AngularVelocity, h);
                            Quaternion turned = body.DeltaRotation * c._startRotation[k];
                            body.InverseInertia = AxisLockMath.ProjectInertia(
                                Mat3.RotateDiagonal(Mat3.FromQuaternion(turned * s.InertiaFrame[slot]), ii), locks);
                            continue;
                        }
                        Quaternion start0 = c._startRotation[k];
                        Quaternion q = body.DeltaRotation * start0;
                        Integrator.RotateFreeBody(ref q, ref body.AngularVelocity, ii, s.InertiaFrame[slot], h);
                        body.DeltaRotation = q * Quaternion.Conjugate(start0);
                        // The joints' impulses in the next substep act on the body as it is
                        // turned now: a body that turns a radian in a step under impulses
                        // computed with its start-of-step inertia gained energy (WorldFuzz).
                        body.InverseInertia = Mat3.RotateDiagonal(Mat3.FromQuaternion(q * s.InertiaFrame[slot]), ii);
                    }
                    return;
                }
                float maxSpeed = c._settings.MaxLinearSpeed;
                for (int k = start; k < end; k++)
                {
                    ref SolverBody body = ref bodies[k];
                    if (body.IsDynamic == 0) continue;
                    kicks[k].Apply(maxSpeed, ref body.LinearVelocity, ref body.AngularVelocity);
                }
            }
        }

        /// <summary>
        /// Applies the accumulated impulses of every constraint. The wide contacts also take their
        /// separations at the bodies' pose now, which the biased passes that follow read.
        /// </summary>
        public void WarmStart() => RunColors(ColorPass.WarmStart);

        /// <summary>
        /// One Gauss-Seidel pass over every constraint, colour by colour; biased (soft, pushing out)
        /// or not (relax). A biased pass takes the wide contacts' separations from the last
        /// <see cref="WarmStart"/>: the bodies must not have moved since. With <paramref name="trees"/>
        /// the joint trees' block (<see cref="JointTreeSolver"/>) is solved after the sweep.
        /// </summary>
        public void Solve(bool useBias, bool trees = true)
        {
            RunColors(useBias ? ColorPass.Solve : ColorPass.Relax);
            // The joint trees' rows, as one block after the sweep (block Gauss-Seidel), where the
            // caller asks for it (TGS: the last biased sweep of a substep and the relax sweep).
            if (trees && _trees.DirectCount > 0) _trees.Solve(Bodies, _joints.Data, _jointParameters.Joint, _jointParameters.H, useBias);
        }

        /// <summary>
        /// Picks the joints whose anchor rows <see cref="Solve"/> solves exactly as trees
        /// (<see cref="JointTreeSolver"/>); with <paramref name="enabled"/> false every joint's rows
        /// stay in the Gauss-Seidel passes. After <see cref="Prepare"/>.
        /// </summary>
        public void BuildJointTrees(bool enabled) => _trees.Build(Bodies, BodyCount, _joints.Data, JointOrder, JointCount, _jointParameters.Joint, _dt, enabled);

        /// <summary>Restitution's free approach speeds from the velocities now (TGS, each substep; see ContactSolver.RecordImpact).</summary>
        public void RefreshApproach() => RunColors(ColorPass.Approach);

        /// <summary>The restitution pass over every contact.</summary>
        public void ApplyRestitution() => RunColors(ColorPass.Restitution);

        /// <summary>One non-linear Gauss-Seidel position pass (PGS).</summary>
        public void SolvePositions() => RunColors(ColorPass.Position);

        /// <summary>Below this ratio of the upper body's mass to the lower one's, the position passes move both.</summary>
        const float HeldMassRatio = 30f;

        /// <summary>
        /// Marks, for PGS's position passes, the contacts whose lower body (in the shock
        /// propagation's levels) is at least <see cref="HeldMassRatio"/> times lighter than the
        /// upper one: the passes then hold the lower body still, move the upper body alone, and
        /// only past <see cref="WorldSettings.ShockDepth"/>, where the sweep rests such a pair.
        /// A correction shared by mass moves the light body nearly all the way: a 100 or 1000 kg
        /// box on a 1 kg one on a 25 degree ramp (mu 0.6) pressed the light box into the ramp
        /// every pass, the ramp pushed it back along a normal of its own, and the light box
        /// walked up the ramp at 1-2 cm/s while the load slid down off it. Call after
        /// <see cref="Prepare"/> and <see cref="PrepareShock"/>.
        /// </summary>
        public void HoldLightSupports()
        {
            if (_held.Length < ContactCount) _held = new byte[Math.Max(16, 2 * ContactCount)];
            Array.Clear(_held, 0, ContactCount);
            if (!_shock.Levelled) return;
            for (int i = 0; i < ContactCount; i++)
            {
                ref ContactConstraint c = ref Contacts[i];
                int la = _shock.LevelOf(c.BodyA), lb = _shock.LevelOf(c.BodyB);
                if (la == lb || la == int.MaxValue || lb == int.MaxValue) continue;
                ref SolverBody a = ref Bodies[c.BodyA];
                ref SolverBody b = ref Bodies[c.BodyB];
                if (a.IsDynamic == 0 || b.IsDynamic == 0) continue;
                if (la < lb ? b.InverseMass * HeldMassRatio <= a.InverseMass : a.InverseMass * HeldMassRatio <= b.InverseMass)
                    _held[i] = (byte)(la < lb ? 1 : 2);
            }
        }

        // Colour by colour: the constraints of one colour touch disjoint dynamic bodies, so with
        // a worker pool they are split between threads; the overflow batch runs on the caller.
        void RunColors(ColorPass pass)
        {
            ColorJob job = _colorJob;
            job.Pass = pass;
            for (int c = 0; c < Buckets; c++)
            {
                job.WideStart = _wideStart[c];
                job.WideCount = _wideStart[c + 1] - _wideStart[c];
                job.ContactStart = _scalarStart[c];
                job.ContactCount = _scalarStart[c + 1] - _scalarStart[c];
                job.JointStart = _jointStart[c];
                int count = job.WideCount + job.ContactCount + (_jointStart[c + 1] - _jointStart[c]);
                if (count == 0) continue;
                // A wide group is a vector's worth of manifolds: split those finer.
                int minChunk = 2 * job.WideCount > count ? MinChunk / 8 : MinChunk;
                if (Pool != null && c < ConstraintColoring.MaxColors) Pool.For(job, 0, count, minChunk);
                else job.Execute(0, count);
            }
        }

        /// <summary>Constraints (or bodies) a thread takes at a time: below this, splitting costs more than it saves.</summary>
        const int MinChunk = 32;

        enum ColorPass : byte { WarmStart, Solve, Relax, Restitution, Approach, Position }

        /// <summary>One pass over the items [start, end) of a colour: its contacts, then its joints.</summary>
        sealed class ColorJob : IParallelJob
        {
            readonly SolverContext _c;
            public ColorPass Pass;
            public int WideStart, WideCount, ContactStart, ContactCount, JointStart;

            public ColorJob(SolverContext context) => _c = context;

            public void Execute(int start, int end)
            {
                SolverContext c = _c;
                c.RunWide(Pass, WideStart, WideCount, start, end);
                start = Math.Max(start, WideCount) - WideCount;
                end -= WideCount;
                if (end <= 0) return;
                int contactEnd = Math.Min(end, ContactCount);
                for (int i = start; i < contactEnd; i++)
                {
                    ref ContactConstraint k = ref c.Contacts[c._scalarContacts[ContactStart + i]];
                    switch (Pass)
                    {
                        case ColorPass.WarmStart: ContactSolver.WarmStart(ref k, c.Points, c.Bodies); break;
                        case ColorPass.Solve: ContactSolver.Solve(ref k, c.Points, c.Bodies, c._contactStep, true); break;
                        case ColorPass.Relax: ContactSolver.Solve(ref k, c.Points, c.Bodies, c._contactStep, false); break;
                        case ColorPass.Restitution: ContactSolver.ApplyRestitution(ref k, c.Points, c.Bodies, c._contactStep.RestitutionThreshold); break;
                        case ColorPass.Approach: ContactSolver.RefreshApproach(ref k, c.Points, c.Bodies); break;
                        default: ContactPositionSolver.Solve(ref k, c.Points, c.Bodies, c._contactStep, c._held[c._scalarContacts[ContactStart + i]], c._settings.ShockDepth); break;
                    }
                }
                if (Pass == ColorPass.Restitution || Pass == ColorPass.Approach) return;
                JointSolver.Pass jointPass = Pass == ColorPass.WarmStart ? JointSolver.Pass.WarmStart
                    : Pass == ColorPass.Solve ? JointSolver.Pass.Solve
                    : Pass == ColorPass.Relax ? JointSolver.Pass.Relax
                    : JointSolver.Pass.Position;
                for (int i = Math.Max(start, ContactCount); i < end; i++)
                    c.RunJoint(ref c._joints.Data[c.JointOrder[JointStart + i - ContactCount]], jointPass);
            }
        }
    }
}
