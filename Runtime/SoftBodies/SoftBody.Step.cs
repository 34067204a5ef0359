using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    public sealed partial class SoftBody
    {
        ElementRangeJob? _tetJob;
        Vector3[]? _target;                 // Newton: the substep's inertial targets
        MembraneRangeJob? _membraneJob;
        BendingRangeJob? _bendingJob;
        // Inertia scaling against much heavier rigid bodies (see ScaleInertia): the factor this
        // step, and the unscaled masses to put back at its end.
        float _inertiaScale = 1f;
        float[]? _baseW, _baseFreeW, _baseM;

        /// <summary>
        /// The soft body's inertia is scaled up for a step to at least the mass of the heaviest
        /// dynamic body resting on it (<see cref="ShapeContactSolver.HeaviestBody"/>) divided by
        /// this (see <see cref="ScaleInertia"/>): 0.5, so
        /// twice that mass. Measured: at 2 (half the mass) plates settled as well, but a 1000 kg
        /// crate dropped on a 43 kg slab kept rocking at 0.1 m/s after 5 s; at 0.5 it rests.
        /// </summary>
        internal static float InertiaRatio = 0.5f;

        /// <summary>The velocity gravity adds in a substep of <paramref name="h"/> (in the step's scaled masses).</summary>
        internal Vector3 GravityStep(float h) => World.Gravity * (GravityScale * h / _inertiaScale);

        /// <summary>Once per world step, before the substeps: find the shapes and pairs the step may touch.</summary>
        internal void BeginStep(float dt, RigidCoupling coupling)
        {
            Array.Copy(X, XStart, X.Length);
            Array.Copy(V, VStart, V.Length);
            Array.Clear(XResidual, 0, XResidual.Length);
            Contacts.KeepStepStart();
            SubstepsBegun = 0;
            if (CollideWithShapes) Contacts.Gather(World, this, dt, coupling);
            AttachmentSolver.Track(World, this, coupling);
            NewtonSolver?.ForgetCondensed();
            SelfContacts?.FindPairs(X, V, dt);
            float heaviest = CollideWithShapes ? Contacts.HeaviestBody(World, X, Down()) : 0f;
            // An attached body hangs its weight on this body only when a pin holds this body to
            // the world (a rope or a sheet hung from a point); otherwise the bodies carry it (a
            // cloth pinned to a pole) or the two move freely together, and the scaling, which
            // also divides this body's weight, would make it float and hand the bodies its
            // scaled momentum: a 533 kg body spinning with a 1 kg cloth pinned to it gained
            // 1e8 J within two steps. (Counting a static shape within reach as a hold as well,
            // for a body pinned on a ball that lies on the ground, brought that gain back as
            // soon as the cloth came near the ground.)
            // And a body attached to a dynamic body but pinned to nothing moves with that body: its
            // inertia is not scaled at all, since the attachments hand the body the scaled
            // momentum (the scale times the soft body's own): a 0.16 kg box pinned to a 3.8 t
            // body spinning at 17 rad/s, scaled 9500 times for a 778 kg box it swept past,
            // doubled the 3.8 t body's speed within a step (soft fuzz seed 229).
            if (Attachments.Length > 0)
            {
                float attached = AttachmentSolver.HeaviestBody(World, Attachments);
                if (HasPinnedVertex()) heaviest = MathF.Max(heaviest, attached);
                else if (attached > 0f) heaviest = 0f;
            }
            ScaleInertia(heaviest / (InertiaRatio * TotalMass));
            if (Tets.Length > 0)
            {
                TetData.Pack(W, FreeW, M);
                // The last step's end measured J on these very positions: with no tet inverted
                // there is nothing to mark (the common case: one J pass per step, not two).
                if (!_cleanEnd) _startLargestJ = VolumeFloor.Measure(TetData, X, mark: true, out _);
                _cleanEnd = false;
                // Loaded from outside: it may touch a rigid shape, is attached to a body, or hangs
                // from a pin (the pin carries its weight: see VolumeFloor).
                TetData.Loaded = Touching || HasPinnedVertex();
            }
        }

        // Whether some vertex is pinned (held in place).
        bool HasPinnedVertex()
        {
            for (int i = 0; i < W.Length; i++) if (W[i] == 0f) return true;
            return false;
        }

        // The unit direction of this body's gravity (zero without gravity).
        Vector3 Down()
        {
            Vector3 g = World.Gravity * GravityScale;
            float length = g.Length();
            return length > 0f ? g / length : Vector3.Zero;
        }

        /// <summary>
        /// Scales the body's inertia by <paramref name="scale"/> (when above 1) for this step,
        /// keeping its weight. Gauss-Seidel XPBD moves each side of a constraint in proportion to
        /// its inverse mass, so a rigid body a thousand times heavier than the vertices under it
        /// is pushed a thousandth of each correction and sinks through a stiff body long before
        /// its weight is carried (a 2000 kg plate on an 8 kg cube at E = 1e7 Pa reached the
        /// floor). With the soft body's inertia scaled to twice the rigid body's mass the two
        /// share each correction and the weight reaches the ground in a few iterations.
        /// Gravity's displacement is divided by the same factor, so every vertex still weighs
        /// m g and the static equilibrium (the strain under the load) is exactly the unscaled
        /// one; what changes is the soft body's own motion while it carries the heavy body (its
        /// waves are slower by the square root of the factor, and it falls at g / scale if it
        /// falls with it). Undone in <see cref="EndStep"/>.
        /// </summary>
        void ScaleInertia(float scale)
        {
            _inertiaScale = scale > 1f ? scale : 1f;
            if (_inertiaScale == 1f) return;
            int n = X.Length;
            if (_baseW == null || _baseW.Length != n)
            {
                _baseW = new float[n];
                _baseFreeW = new float[n];
                _baseM = new float[n];
            }
            Array.Copy(W, _baseW, n);
            Array.Copy(FreeW, _baseFreeW!, n);
            Array.Copy(M, _baseM!, n);
            float inverse = 1f / _inertiaScale;
            for (int i = 0; i < n; i++)
            {
                W[i] *= inverse;
                FreeW[i] *= inverse;
                M[i] *= _inertiaScale;
            }
        }

        /// <summary>
        /// A tet's volume ratio |J| beyond which a body whose largest |J| grew more than
        /// <see cref="BlowUpGrowth"/> times in one step counts as blown apart: 10. No elastic
        /// material of the stiffness of rubber changes volume tenfold (the stable Neo-Hookean
        /// energy there is at least 40 lambda per unit volume), and an exploding solve grows it by
        /// orders of magnitude a step.
        /// </summary>
        public const float MaxVolumeRatio = 10f;

        /// <summary>
        /// How many times its step-start value the largest |J| must reach within one step, beyond
        /// <see cref="MaxVolumeRatio"/>, to count as blowing apart: 2. A very soft body squeezed
        /// out from under a heavy one stretches past tenfold too, a few percent a step, and comes
        /// back (a 2.9 kg sphere of E 1.9e3 Pa under a 1 t body: 9.45 -&gt; 10.75 in a step, then
        /// back to 3-5; soft fuzz seed 991): put back at rest there, it froze in mid-air.
        /// </summary>
        public const float BlowUpGrowth = 2f;

        /// <summary>The |J| no tet may reach at all (unless one was beyond it at the start of the step): 100.</summary>
        public const float MaxStretch = 100f;

        // The largest |J| at the start of this step (VolumeFloor.Measure, here or at the last step's end).
        float _startLargestJ;
        // The last step ended with no tet inverted and nothing has moved a vertex since.
        bool _cleanEnd;

        /// <summary>Forgets what the last step's end measured (call after anything moves a vertex between steps).</summary>
        internal void PositionsChanged() => _cleanEnd = false;

        /// <summary>Whether the last <see cref="KeepFinite"/> found the body diverged (and put it back).</summary>
        internal bool DivergedInStep;

        // What Blown measured at the end of the substeps: the largest |J|, whether a tet was
        // inverted, and whether it holds for KeepFinite (nothing has moved a vertex or changed
        // a rest shape since).
        float _endLargestJ;
        bool _endInverted, _endBlown, _endMeasured;

        /// <summary>
        /// Whether the substeps left a vertex position or velocity non-finite or outside the world
        /// bounds, or blew a tet apart (its |J| beyond <see cref="MaxVolumeRatio"/> and more than
        /// <see cref="BlowUpGrowth"/> times the step-start largest, or beyond <see cref="MaxStretch"/>;
        /// tets holding a pinned vertex are left out, see <see cref="VolumeFloor.Measure"/>).
        /// Changes no vertex; <see cref="KeepFinite"/> acts on what it found.
        /// </summary>
        internal bool Blown()
        {
            float bound = Limits.MaxPosition;
            bool bad = false;
            for (int i = 0; i < X.Length && !bad; i++)
            {
                Vector3 x = X[i], v = V[i];
                bad = !float.IsFinite(x.X + x.Y + x.Z + v.X + v.Y + v.Z)
                    || MathF.Abs(x.X) > bound || MathF.Abs(x.Y) > bound || MathF.Abs(x.Z) > bound;
            }
            // Blown apart: a tet whose volume ratio went beyond MaxVolumeRatio, growing more than
            // BlowUpGrowth times in one step (finite, but no material stores that: the first step
            // of an explosion, which otherwise ran on to 1e25 J of strain within the world bounds).
            _endInverted = false;
            _endLargestJ = 0f;
            if (!bad && Tets.Length > 0)
            {
                _endLargestJ = VolumeFloor.Measure(TetData, X, mark: false, out _endInverted);
                bad = !(_endLargestJ <= MaxVolumeRatio || _endLargestJ <= BlowUpGrowth * _startLargestJ)
                    || _startLargestJ <= MaxStretch && !(_endLargestJ <= MaxStretch);
            }
            _endBlown = bad;
            _endMeasured = true;
            return bad;
        }

        /// <summary>
        /// Puts the body back as the step found it, to take the step again: positions and
        /// velocities, its unscaled inertia, and what its contacts remembered from the last step.
        /// </summary>
        internal void RollBack()
        {
            Array.Copy(XStart, X, X.Length);
            Array.Copy(XStart, XPrev, X.Length);
            Array.Copy(VStart, V, V.Length);
            RestoreInertia();
            Contacts.BackToStepStart();
            _endMeasured = false;
        }

        /// <summary>
        /// True when <see cref="Blown"/> (measured again here if the rest shapes changed since, by
        /// plastic flow) found the body whole; otherwise puts every vertex back at its step-start
        /// position at rest and returns false.
        /// </summary>
        internal bool KeepFinite()
        {
            bool bad = _endMeasured && !(Plasticity.Enabled && Tets.Length > 0) ? _endBlown : Blown();
            _endMeasured = false;
            if (!bad && Tets.Length > 0)
            {
                _startLargestJ = _endLargestJ;
                _cleanEnd = !_endInverted;
            }
            DivergedInStep = bad;
            if (!bad) return true;
            Array.Copy(XStart, X, X.Length);
            Array.Copy(XStart, XPrev, X.Length);
            Array.Clear(V, 0, V.Length);
            return false;
        }

        /// <summary>
        /// One XPBD substep of length <paramref name="h"/>: predict with gravity; per iteration
        /// project contacts, the elastic constraints (multipliers start at zero and are kept
        /// across the iterations) and attachments; velocities from the change in position; then
        /// the stiffness-proportional damping as a velocity pass (<see cref="RayleighDamping"/>).
        /// </summary>
        internal void Substep(float h, RigidCoupling coupling, IParallelScheduler? pool)
        {
            SubstepsBegun++;
            // Newton: the energy of the body and the rigid bodies it moves before the substep, for
            // the guard after it.
            bool guard = Solver == SoftSolver.Newton;
            double before = 0;
            if (guard)
            {
                coupling.Snapshot();
                before = Energy() + coupling.Energy(World.Gravity);
            }
            Vector3 dv = GravityStep(h);
            float keep = LinearDamping > 0 ? 1f / (1f + LinearDamping * h) : 1f;
            if (Solver == SoftSolver.Newton)
            {
                // The Newton step takes its own velocities from the positions (see EndPositions).
                for (int i = 0; i < X.Length; i++)
                {
                    XPrev[i] = X[i];
                    if (W[i] == 0f) continue;
                    V[i] = (V[i] + dv) * keep;
                    X[i] += V[i] * h;
                }
            }
            else
            {
                for (int i = 0; i < X.Length; i++)
                {
                    Vector3 x = X[i];
                    XPrev[i] = x;
                    XPredicted[i] = x;
                    if (W[i] == 0f) continue;
                    V[i] = (V[i] + dv) * keep;
                    // The move plus what earlier substeps' moves lost to rounding, summed exactly
                    // (Knuth's two-sum): far from the origin a float position cannot take a small
                    // move (at 600 m positions are 6e-5 m apart, a first substep's fall 2.7e-5 m).
                    Vector3 d = V[i] * h + XResidual[i];
                    Vector3 sum = x + d;
                    Vector3 taken = sum - x;
                    XResidual[i] = (x - (sum - taken)) + (d - taken);
                    X[i] = sum;
                    XPredicted[i] = sum;
                }
            }
            Array.Clear(TetLambda, 0, TetLambda.Length);
            Array.Clear(TriLambda, 0, TriLambda.Length);
            Array.Clear(BendLambda, 0, BendLambda.Length);
            if (CollideWithShapes) Contacts.BeginSubstep(X.Length);
            if (Solver == SoftSolver.Newton)
            {
                SubstepNewton(h, coupling);
                if (guard) GuardEnergy(before, h, coupling);
                return;
            }
            for (int iteration = 0; iteration < Iterations; iteration++)
            {
                // Contacts before the elastic pass: projected after it, they keep re-straining
                // the elements that touch the ground, and a stiff body settles with that strain
                // locked in (a cube at E = 1e9 Pa kept 1.2e4 J; this order leaves 185 J).
                if (CollideWithShapes) Contacts.Solve(World, this, h, coupling, normal: true);
                RunElements(h, damping: false, pool);
                if (Attachments.Length > 0) AttachmentSolver.Solve(World, this, X, W, h, coupling);
            }
            EndPositions(h, coupling);
            if (DampingTime > 0f)
            {
                RunElements(h, damping: true, pool);
                if (Attachments.Length > 0) AttachmentSolver.HandDampingToBodies(World, Attachments, X, V, W, coupling);
            }
        }

        /// <summary>
        /// The rest of a substep with <see cref="SoftSolver.Newton"/>: the predicted positions are the
        /// inertial targets; per iteration one Newton step of implicit Euler, then contacts and
        /// attachments projected; friction; velocities from the positions. Damping is part of
        /// the Newton step (no separate velocity pass). Friction against shapes comes after the
        /// last iteration's step only, bounded by the normal impulse that step measured: each
        /// step starts from the positions the last one left and pulls the body back to its
        /// inertial target, undoing an earlier pass's friction while the cone it spent stayed
        /// spent (with friction after each of two iterations, and the larger of their supports, a
        /// Newton cube held on every slope it should have slid down).
        /// </summary>
        void SubstepNewton(float h, RigidCoupling coupling)
        {
            if (_target == null || _target.Length != X.Length) _target = new Vector3[X.Length];
            Array.Copy(X, _target, X.Length);
            for (int iteration = 0; iteration < Iterations; iteration++)
            {
                if (iteration > 0 && CollideWithShapes) Contacts.ReplaceSupport();
                NewtonSolver!.Step(this, _target, h, coupling);
                // A vertex the step took into a shape is held by the next step's overlap spring
                // rather than pushed out alone by the contact pass (ImplicitNewtonSolver.Entered).
                if (NewtonSolver.Entered(this, ImplicitNewtonSolver.EnterTolerance))
                {
                    if (iteration > 0 && CollideWithShapes) Contacts.ReplaceSupport();
                    NewtonSolver.Step(this, _target, h, coupling);
                }
                if (CollideWithShapes) Contacts.Solve(World, this, h, coupling, normal: true, friction: iteration == Iterations - 1);
                if (Attachments.Length > 0) AttachmentSolver.SolveEach(World, Attachments, X, W, h, coupling);
                // After the contacts, as the XPBD pass's floor comes after them: what a heavy body
                // pressed on the tets is taken back before the next Newton step sees it.
                if (Tets.Length > 0) VolumeFloor.HoldAll(TetData, X, 0, Tets.Length);
            }
            NewtonSolver!.PushSoftBodies(this, h);
            EndPositions(h, coupling);
        }

        /// <summary>
        /// The end of a substep's position solve (XPBD or Newton): friction, self-contacts, and the
        /// velocities from the change in position (zero for pinned vertices).
        /// </summary>
        void EndPositions(float h, RigidCoupling coupling)
        {
            // Friction again after the elastic pass, on the substep's whole slip, within what is
            // left of the cone: measured only up to the contact pass it missed the slip the
            // elastic pass adds, and a jelly crept 4 cm/s down a 30 degree slope with mu = 0.8.
            // (Not the normal constraint: projected after the elastic pass it locks strain in.)
            if (CollideWithShapes) Contacts.Solve(World, this, h, coupling, normal: false);
            SelfContacts?.Solve(X, W);
            float invH = 1f / h;
            if (Solver == SoftSolver.Newton)
            {
                for (int i = 0; i < X.Length; i++) V[i] = W[i] == 0f ? Vector3.Zero : (X[i] - XPrev[i]) * invH;
                if (CollideWithShapes) Contacts.ApplyFrictionVelocities(V, W, invH);
                return;
            }
            // XPBD: v = (x - x_prev) / h, taken as the predicted velocity plus the constraints'
            // moves over h (the difference of two nearby floats is exact), where x - x_prev lost
            // the prediction's rounding, up to half a float spacing per substep. Far from the
            // origin that was most of the motion: a jelly dropped at 50 m fell 2 % slow, at 200 m
            // 12 % fast, and at 600 m not at all (the first move rounded to nothing, so v stayed
            // 0). A vertex a constraint moved is where the constraint put it: what the prediction
            // lost to rounding is dropped, so that a vertex held in place has v = 0 exactly.
            for (int i = 0; i < X.Length; i++)
            {
                if (W[i] == 0f)
                {
                    V[i] = Vector3.Zero;
                    continue;
                }
                Vector3 moved = X[i] - XPredicted[i];
                if (moved == Vector3.Zero) continue;
                V[i] += (moved - XResidual[i]) * invH;
                XResidual[i] = Vector3.Zero;
            }
        }

        /// <summary>Every element family, colour by colour: the position solve, or the damping pass.</summary>
        void RunElements(float h, bool damping, IParallelScheduler? pool)
        {
            if (Tets.Length > 0) RunColors(TetJob().For(h, DampingTime, damping), TetColors, pool, damping ? 1 : 0);
            if (Tris.Length > 0) RunColors((_membraneJob ??= new MembraneRangeJob(this)).For(h, DampingTime, damping), TriColors, pool, damping ? 3 : 2);
            if (Bends.Length > 0) RunColors((_bendingJob ??= new BendingRangeJob(this)).For(h, DampingTime, damping), BendColors, pool, damping ? 5 : 4);
        }

        /// <summary>
        /// The body's kinetic, gravitational and elastic energy, J (in the step's scaled masses;
        /// pinned vertices carry none).
        /// </summary>
        double Energy()
        {
            Vector3 g = World.Gravity * (GravityScale / _inertiaScale);
            double e = 0;
            for (int i = 0; i < X.Length; i++)
            {
                if (W[i] == 0f) continue;
                e += M[i] * (0.5 * V[i].LengthSquared() - Vector3.Dot(g, X[i]));
            }
            for (int k = 0; k < Tets.Length; k++)
            {
                ref TetElement t = ref Tets[k];
                float psi = SoftBodyMeasures.EnergyDensity(this, DeformationGradient.Of(X[t.A], X[t.B], X[t.C], X[t.D], t.RestInverse));
                if (float.IsFinite(psi)) e += t.RestVolume * psi;
            }
            return e;
        }

        /// <summary>
        /// The Newton substep's energy guard. Implicit Euler only dissipates, and so do the
        /// contacts and attachments it shares with rigid bodies, but the contact pass after the
        /// Newton step pushes vertices out of a shape on their own, and in a nearly
        /// incompressible body (linear tets lock: lambda thousands of times mu) each push stores
        /// far more strain energy than the body's motion holds: a nu = 0.4999 cube thrown at the
        /// ground at 13 m/s went from 0.014 J to 308 J of strain in one pass (86 J kinetic), the
        /// next steps released it, and the body blew apart. When the substep ends with more
        /// energy than it began with (the body's kinetic, gravitational and elastic energy and
        /// the kinetic and gravitational energy of the rigid bodies it moved in the substep), the
        /// velocities about the centre of mass of the body and those rigid bodies together are
        /// scaled down until the excess is taken out, or to zero (their momentum is kept, and
        /// the soft body's own spin): the strain is then released over the following substeps,
        /// each bounded the same way.
        /// Before the rigid bodies were counted, the guard stood aside whenever one was touching
        /// or attached: a 239 kg body dropped 3 m onto a 1.4 kg nu = 0.4999 jelly box blew it
        /// apart (soft fuzz seed 358; now min J stays above 0.95 and the energy only falls), and
        /// 12 of the 21 divergent worlds of seeds 200-399 were of that kind.
        /// </summary>
        void GuardEnergy(double before, float h, RigidCoupling coupling)
        {
            double excess = Energy() + coupling.Energy(World.Gravity) - before;
            if (!(excess > 1e-6 * Math.Abs(before) + 1e-9 + coupling.Slack(h))) return;
            BodyStorage b = World.Bodies;
            double mass = 0;
            Vector3 momentum = Vector3.Zero;
            for (int i = 0; i < X.Length; i++)
            {
                if (W[i] == 0f) continue;
                mass += M[i];
                momentum += M[i] * V[i];
            }
            for (int e = 0; e < coupling.Count; e++)
            {
                if (!coupling.Changed(e)) continue;
                int slot = coupling.SlotOf(e);
                mass += b.Mass[slot];
                momentum += b.Mass[slot] * b.LinearVelocity[slot];
            }
            if (!(mass > 0)) return;
            Vector3 mean = momentum / (float)mass;
            // The soft body's own spin (about its centre of mass) is scaled last: scaled with the
            // rest, a spinning Newton body that wobbled lost its spin (a cube kicked at its base
            // while turning at 1 rad/s kept 1 % of its angular momentum). Scaled first: the
            // deformation velocity, the body's motion relative to the common mean, and the rigid
            // bodies' motion; the spin only when they cannot cover the excess.
            RigidFit.Fit(X, V, M, W, X.Length, out Vector3 centre, out Vector3 own, out Vector3 spin);
            double internalKinetic = 0, softMass = 0, spinKinetic = 0;
            for (int i = 0; i < X.Length; i++)
            {
                if (W[i] == 0f) continue;
                Vector3 turning = Vector3.Cross(spin, X[i] - centre);
                softMass += M[i];
                internalKinetic += 0.5 * M[i] * (V[i] - own - turning).LengthSquared();
                spinKinetic += 0.5 * M[i] * turning.LengthSquared();
            }
            internalKinetic += 0.5 * softMass * (own - mean).LengthSquared();
            for (int e = 0; e < coupling.Count; e++)
            {
                if (!coupling.Changed(e)) continue;
                int slot = coupling.SlotOf(e);
                internalKinetic += 0.5 * b.Mass[slot] * (b.LinearVelocity[slot] - mean).LengthSquared() + coupling.RotationalEnergy(slot);
            }
            if (!(internalKinetic + spinKinetic > 0)) return;
            float scale = internalKinetic > 0 ? (float)Math.Sqrt(Math.Max(0, 1 - excess / internalKinetic)) : 0f;
            float spinScale = excess > internalKinetic && spinKinetic > 0 ? (float)Math.Sqrt(Math.Max(0, 1 - (excess - internalKinetic) / spinKinetic)) : 1f;
            for (int i = 0; i < X.Length; i++)
            {
                if (W[i] == 0f) continue;
                Vector3 turning = Vector3.Cross(spin, X[i] - centre);
                V[i] = mean + scale * (own - mean) + spinScale * turning + scale * (V[i] - own - turning);
            }
            for (int e = 0; e < coupling.Count; e++)
            {
                if (!coupling.Changed(e)) continue;
                int slot = coupling.SlotOf(e);
                b.LinearVelocity[slot] = mean + scale * (b.LinearVelocity[slot] - mean);
                b.AngularVelocity[slot] *= scale;
            }
        }

        /// <summary>Once per world step, after the substeps.</summary>
        internal void EndStep(float dt)
        {
            RestoreInertia();
            if (Plasticity.Enabled && Tets.Length > 0)
            {
                PlasticFlow.Apply(this, dt);
                TetData.LoadElements(Tets);
            }
        }

        // The unscaled masses back after a step that scaled them (ScaleInertia).
        void RestoreInertia()
        {
            if (_inertiaScale == 1f) return;
            Array.Copy(_baseW!, W, W.Length);
            Array.Copy(_baseFreeW!, FreeW, FreeW.Length);
            Array.Copy(_baseM!, M, M.Length);
            _inertiaScale = 1f;
        }

        // The tet job, specialised for the body's material model (which does not change).
        ElementRangeJob TetJob() => _tetJob ??= Material.Model == MaterialModel.NeoHookean
            ? new TetRangeJob<NeoHookeanEnergy>(this, ClassicModel)
            : new TetRangeJob<StableNeoHookeanEnergy>(this, StableModel);

        // Elements a thread takes at a time: a colour of fewer than two such chunks runs on the
        // caller. A multiple of eight, the tet kernels' block. Whether a pass is split at all is
        // ThreadChoice's measurement: before it, 32-element chunks ran a 10k-tet box 2-3 times
        // slower on 2 loaded threads than on 1, and 256 kept the 10k box's colours (about 350
        // tets each) on the caller at any thread count (7.4 ms on 1 to 16 threads of a
        // 16-core machine).
        const int MinChunk = 64;

        // Pool or calling thread, per element family and pass (tets, membranes, bends; position or damping).
        readonly ThreadChoice[] _threadChoice = { new ThreadChoice(), new ThreadChoice(), new ThreadChoice(), new ThreadChoice(), new ThreadChoice(), new ThreadChoice() };

        void RunColors(RangeJob job, int[] colors, IParallelScheduler? pool, int choice)
        {
            if (pool == null)
            {
                for (int c = 0; c + 1 < colors.Length; c++) job.Execute(colors[c], colors[c + 1]);
                return;
            }
            ThreadChoice chooser = _threadChoice[choice];
            bool parallel = chooser.Begin();
            for (int c = 0; c + 1 < colors.Length; c++)
            {
                if (parallel) pool.For(job, colors[c], colors[c + 1], MinChunk);
                else job.Execute(colors[c], colors[c + 1]);
            }
            chooser.End(colors[colors.Length - 1]);
        }
    }
}
