#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The SIMD path of <see cref="ContactSolver"/> (net10 only; the scalar path is the
    /// reference and runs everywhere else): the same warm start, block-pair normal solve, patch
    /// friction, restitution and write-back, for a group of four-point manifolds of one colour at
    /// a time. The manifolds of a colour share no dynamic body, so the lanes are independent;
    /// the bodies' velocities are gathered into lanes before a pass and scattered back after.
    /// Used for manifolds of four points whose two block pairs are well conditioned and that have
    /// no rolling resistance (boxes on boxes, the bulk of stacks and piles); the rest stay scalar.
    /// (PGS's position pass runs scalar on the same constraints: it needs only their geometry.) The block LCP's four cases are all evaluated and the first that holds is
    /// selected per lane, as the scalar enumeration does.
    /// </summary>
    internal static partial class ContactSolverWide
    {
        public static int Width => Vector<float>.Count;

        /// <summary>True for a manifold the wide path can take.</summary>
        public static bool Accepts(in ContactConstraint c) =>
            Vector.IsHardwareAccelerated && c.PointCount == 4 && c.Block0.IsUsed && c.Block1.IsUsed && c.RollingFriction == 0;

        /// <summary>
        /// The <see cref="ContactStep"/> in lanes: the softness of a normal row against a moving
        /// body and against a fixed one, 1 / substep and the push speed bound.
        /// </summary>
        readonly struct StepLanes
        {
            public readonly Vector<float> BiasRate, MassScale, ImpulseScale, FixedBiasRate, FixedMassScale, FixedImpulseScale;
            public readonly Vector<float> InverseStep, MaxPush;

            public StepLanes(in ContactStep step)
            {
                ref readonly Softness contact = ref step.Contact;
                ref readonly Softness fixedBody = ref step.FixedBody;
                InverseStep = new Vector<float>(step.InverseH);
                MaxPush = new Vector<float>(-step.MaxPushSpeed);
                BiasRate = new Vector<float>(contact.BiasRate);
                MassScale = new Vector<float>(contact.MassScale);
                ImpulseScale = new Vector<float>(contact.ImpulseScale);
                FixedBiasRate = new Vector<float>(fixedBody.BiasRate);
                FixedMassScale = new Vector<float>(fixedBody.MassScale);
                FixedImpulseScale = new Vector<float>(fixedBody.ImpulseScale);
            }
        }

        /// <summary>J v of a row along <paramref name="d"/> with angular parts <paramref name="angularA"/>, <paramref name="angularB"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<float> RowVelocity(in WideVector3 angularA, in WideVector3 angularB, in WideVector3 d, in BodyLanes l)
        {
            WideVector3 dv = l.VB;
            dv.Subtract(l.VA);
            return WideVector3.Dot(d, dv) + WideVector3.Dot(angularB, l.WB) - WideVector3.Dot(angularA, l.WA);
        }

        /// <summary>
        /// Applies the linear impulse <paramref name="linear"/> and the angular impulses
        /// <paramref name="angularA"/> (taken from A) and <paramref name="angularB"/> (given to B).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Apply(in WideVector3 linear, in WideVector3 angularA, in WideVector3 angularB, ref BodyLanes l)
        {
            l.VA.SubtractScaled(linear, l.InvMassA);
            l.VB.AddScaled(linear, l.InvMassB);
            l.WA.Subtract(l.IA.Transform(angularA));
            l.WB.Add(l.IB.Transform(angularB));
        }

        // The passes run over ranges of groups [first, end). The lanes' stack home is a local of
        // the range method, handed to the per-group methods by reference: a local of theirs is
        // zeroed on every entry (1.4 kB, .locals init) because the gather writes it through out
        // parameters, and the per-group methods are too large to be inlined into the loop.

        /// <summary>The warm start of groups [first, end).</summary>
        public static void WarmStart(WideContact[] groups, int first, int end, SolverBody[] bodies, int[] laneBodies)
        {
            BodyLanes l = default;
            for (int g = first; g < end; g++) WarmStart(ref groups[g], bodies, laneBodies, g * Width, ref l);
        }

        /// <summary>One pass (biased or relaxing) over groups [first, end).</summary>
        public static void Solve(WideContact[] groups, WideImpact[] impacts, int first, int end, SolverBody[] bodies, int[] laneBodies,
            in ContactStep step, bool useBias)
        {
            var soft = new StepLanes(step);
            BodyLanes l = default;
            for (int g = first; g < end; g++)
                Solve(ref groups[g], ref impacts[g], bodies, laneBodies, g * Width, soft, useBias, ref l);
        }

        /// <summary>ContactSolver.RefreshApproach for groups [first, end).</summary>
        public static void RefreshApproach(WideContact[] groups, WideImpact[] impacts, int first, int end, SolverBody[] bodies, int[] laneBodies)
        {
            BodyLanes l = default;
            for (int g = first; g < end; g++) RefreshApproach(ref groups[g], ref impacts[g], bodies, laneBodies, g * Width, ref l);
        }

        /// <summary>The restitution pass of groups [first, end).</summary>
        public static void ApplyRestitution(WideContact[] groups, WideImpact[] impacts, int first, int end, SolverBody[] bodies, int[] laneBodies, float threshold)
        {
            BodyLanes l = default;
            for (int g = first; g < end; g++) ApplyRestitution(ref groups[g], ref impacts[g], bodies, laneBodies, g * Width, threshold, ref l);
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        static void WarmStart(ref WideContact w, SolverBody[] bodies, int[] laneBodies, int groupOffset, ref BodyLanes l)
        {
            WideBodies.Gather(bodies, laneBodies, groupOffset, ref l, true, true);
            // The substep's separations, for its biased passes (the bodies move after those).
            Vector<float> drift = Drift(w.Normal, l);
            w.P0.Current = Separation(w.P0, drift, l);
            w.P1.Current = Separation(w.P1, drift, l);
            w.P2.Current = Separation(w.P2, drift, l);
            w.P3.Current = Separation(w.P3, drift, l);
            Vector<float> l0 = w.P0.Impulse, l1 = w.P1.Impulse, l2 = w.P2.Impulse, l3 = w.P3.Impulse;
            Vector<float> f1 = w.FrictionImpulse1, f2 = w.FrictionImpulse2;
            Tangents(w.Normal, out WideVector3 t1, out WideVector3 t2);
            WideVector3 friction = WideVector3.Scale(t1, f1);
            friction.AddScaled(t2, f2);
            WideVector3 linear = WideVector3.Scale(w.Normal, l0 + l1 + l2 + l3);
            linear.Add(friction);
            WideVector3 angularA = WarmAngular(w, w.CentroidA, friction, w.P0.AngularA, w.P1.AngularA, w.P2.AngularA, w.P3.AngularA);
            WideVector3 angularB = WarmAngular(w, w.CentroidB, friction, w.P0.AngularB, w.P1.AngularB, w.P2.AngularB, w.P3.AngularB);
            Apply(linear, angularA, angularB, ref l);
            WideBodies.Scatter(bodies, laneBodies, groupOffset, ref l);
        }

        /// <summary>
        /// One body's angular warm-start impulse: the friction's moment about its
        /// <paramref name="centroid"/>, then the four normal rows' angular parts
        /// (<paramref name="a0"/>..<paramref name="a3"/>, that body's side) and the twist row, each
        /// scaled by its accumulated impulse.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static WideVector3 WarmAngular(in WideContact w, in WideVector3 centroid, in WideVector3 friction,
            in WideVector3 a0, in WideVector3 a1, in WideVector3 a2, in WideVector3 a3)
        {
            // The friction rows' angular parts are c x t: their impulse's moment is c x (f1 t1 + f2 t2).
            WideVector3 angular = WideVector3.Cross(centroid, friction);
            angular.AddScaled(a0, w.P0.Impulse);
            angular.AddScaled(a1, w.P1.Impulse);
            angular.AddScaled(a2, w.P2.Impulse);
            angular.AddScaled(a3, w.P3.Impulse);
            angular.AddScaled(w.Normal, w.TwistImpulse);
            return angular;
        }

        /// <summary>n . (dpB - dpA): how far the centres of mass have closed along the normal since the step began.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<float> Drift(in WideVector3 n, in BodyLanes l)
        {
            WideVector3 dp = l.DpB;
            dp.Subtract(l.DpA);
            return WideVector3.Dot(n, dp);
        }

        /// <summary>A point's separation at the bodies' pose now (ContactSolver.Solve's first-order update).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<float> Separation(in WidePoint p, Vector<float> drift, in BodyLanes l) =>
            p.Separation + drift + WideVector3.Dot(l.DThetaB, p.AngularB) - WideVector3.Dot(l.DThetaA, p.AngularA);

        // The relaxing pass's gather: the bodies with their motion, and the separations at their pose.
        // Not inlined: the per-group solve is at the JIT's inlining budget, and SolvePair must fit.
        [MethodImpl(MethodImplOptions.NoInlining)]
        static void GatherMoved(ref WideContact w, SolverBody[] bodies, int[] laneBodies, int groupOffset, ref BodyLanes l,
            out Vector<float> s0, out Vector<float> s1, out Vector<float> s2, out Vector<float> s3)
        {
            WideBodies.Gather(bodies, laneBodies, groupOffset, ref l, true, true);
            Vector<float> drift = Drift(w.Normal, l);
            s0 = Separation(w.P0, drift, l);
            s1 = Separation(w.P1, drift, l);
            s2 = Separation(w.P2, drift, l);
            s3 = Separation(w.P3, drift, l);
        }

        // One pass (biased or relaxing) over a group; the same rows, in the same order, as
        // ContactSolver.Solve. The biased passes of a substep share the pose of its warm start,
        // which stored their separations; the relaxing pass follows the position update and
        // gathers the motion itself.
        [MethodImpl(MethodImplOptions.NoInlining)]
        static void Solve(ref WideContact w, ref WideImpact impact, SolverBody[] bodies, int[] laneBodies, int groupOffset, in StepLanes soft,
            bool useBias, ref BodyLanes l)
        {
            Vector<float> s0, s1, s2, s3;
            if (useBias)
            {
                WideBodies.Gather(bodies, laneBodies, groupOffset, ref l, true, false);
                s0 = w.P0.Current;
                s1 = w.P1.Current;
                s2 = w.P2.Current;
                s3 = w.P3.Current;
            }
            else GatherMoved(ref w, bodies, laneBodies, groupOffset, ref l, out s0, out s1, out s2, out s3);
            Vector<float> inverseStep = soft.InverseStep, maxPush = soft.MaxPush;
            // A body that cannot move makes the contact stiffer (ContactSolver.Prepare).
            var fixedBody = Vector.BitwiseOr(Vector.Equals(Vector.AsVectorInt32(l.FlagA), Vector<int>.Zero),
                Vector.Equals(Vector.AsVectorInt32(l.FlagB), Vector<int>.Zero));
            var rate = WideVector3.Select(fixedBody, soft.FixedBiasRate, soft.BiasRate);
            var massScale = WideVector3.Select(fixedBody, soft.FixedMassScale, soft.MassScale);
            var impulseScale = WideVector3.Select(fixedBody, soft.FixedImpulseScale, soft.ImpulseScale);
            Vector<int> loaded = w.Loaded;
            // The rows' bias and softness hang on the separations only: all four before the
            // velocity-dependent part (which keeps SolvePair's arguments few enough to inline).
            Terms(s0, w.K11a, inverseStep, maxPush, rate, massScale, impulseScale, useBias, out Vector<float> bias0, out Vector<float> gamma0);
            Terms(s1, w.K22a, inverseStep, maxPush, rate, massScale, impulseScale, useBias, out Vector<float> bias1, out Vector<float> gamma1);
            Terms(s2, w.K11b, inverseStep, maxPush, rate, massScale, impulseScale, useBias, out Vector<float> bias2, out Vector<float> gamma2);
            Terms(s3, w.K22b, inverseStep, maxPush, rate, massScale, impulseScale, useBias, out Vector<float> bias3, out Vector<float> gamma3);
            Vector<int> first = SolvePair(ref w.P0, ref w.P1, w.K11a, w.K12a, w.K22a, 1, 2, w.Normal, bias0, gamma0, bias1, gamma1,
                ref loaded, out Vector<float> vn0, out Vector<float> vn1, ref l);
            Vector<int> first2 = SolvePair(ref w.P2, ref w.P3, w.K11b, w.K12b, w.K22b, 4, 8, w.Normal, bias2, gamma2, bias3, gamma3,
                ref loaded, out Vector<float> vn2, out Vector<float> vn3, ref l);
            first = Vector.BitwiseOr(first, first2);
            if (!Vector.EqualsAll(first, Vector<int>.Zero))
            {
                // The approach speed of the (sub)step a point first carries load (RecordImpact).
                RecordImpact(ref impact.P0.RelativeVelocity, first, 1, vn0);
                RecordImpact(ref impact.P1.RelativeVelocity, first, 2, vn1);
                RecordImpact(ref impact.P2.RelativeVelocity, first, 4, vn2);
                RecordImpact(ref impact.P3.RelativeVelocity, first, 8, vn3);
                w.Loaded = loaded;
            }

            Vector<float> total = w.P0.Impulse + w.P1.Impulse + w.P2.Impulse + w.P3.Impulse;
            Vector<float> maxFriction = w.Friction * total;
            Vector<float> old1 = w.FrictionImpulse1, old2 = w.FrictionImpulse2;
            // J v of the rows c x t: t . (the velocity of B's centroid point - A's).
            Tangents(w.Normal, out WideVector3 t1, out WideVector3 t2);
            WideVector3 dv = l.VB;
            dv.Add(WideVector3.Cross(l.WB, w.CentroidB));
            dv.Subtract(l.VA);
            dv.Subtract(WideVector3.Cross(l.WA, w.CentroidA));
            Vector<float> new1 = old1 - w.FrictionMass1 * WideVector3.Dot(t1, dv);
            Vector<float> new2 = old2 - w.FrictionMass2 * WideVector3.Dot(t2, dv);
            Vector<float> len2 = new1 * new1 + new2 * new2;
            Vector<float> scale = WideVector3.Select(Vector.GreaterThan(len2, maxFriction * maxFriction),
                maxFriction / Vector.SquareRoot(len2), Vector<float>.One);
            new1 *= scale;
            new2 *= scale;
            w.FrictionImpulse1 = new1;
            w.FrictionImpulse2 = new2;
            Vector<float> d1 = new1 - old1, d2 = new2 - old2;
            WideVector3 linear = WideVector3.Scale(t1, d1);
            linear.AddScaled(t2, d2);
            WideVector3 angularA = WideVector3.Cross(w.CentroidA, linear);
            WideVector3 angularB = WideVector3.Cross(w.CentroidB, linear);
            Apply(linear, angularA, angularB, ref l);

            Vector<float> maxTwist = maxFriction * w.TwistRadius;
            WideVector3 dw = l.WB;
            dw.Subtract(l.WA);
            Vector<float> oldTwist = w.TwistImpulse;
            Vector<float> twist = Vector.Min(Vector.Max(oldTwist - w.TwistMass * WideVector3.Dot(w.Normal, dw), -maxTwist), maxTwist);
            w.TwistImpulse = twist;
            WideVector3 spin = WideVector3.Scale(w.Normal, twist - oldTwist);
            l.WA.Subtract(l.IA.Transform(spin));
            l.WB.Add(l.IB.Transform(spin));
            WideBodies.Scatter(bodies, laneBodies, groupOffset, ref l);
        }

        // TangentBasis.Build, lane-wise.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Tangents(in WideVector3 n, out WideVector3 t1, out WideVector3 t2)
        {
            Vector<float> sign = WideVector3.Select(Vector.GreaterThanOrEqual(n.Z, Vector<float>.Zero), Vector<float>.One, new Vector<float>(-1f));
            Vector<float> a = new Vector<float>(-1f) / (sign + n.Z);
            Vector<float> b = n.X * n.Y * a;
            t1 = new WideVector3 { X = Vector<float>.One + sign * n.X * n.X * a, Y = sign * b, Z = -sign * n.X };
            t2 = new WideVector3 { X = b, Y = sign + n.Y * n.Y * a, Z = -n.Y };
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void RecordImpact(ref Vector<float> approach, Vector<int> first, int bit, Vector<float> vn)
        {
            var mask = Vector.Equals(Vector.BitwiseAnd(first, new Vector<int>(bit)), new Vector<int>(bit));
            approach = WideVector3.Select(mask, Vector.Max(vn, approach), approach);
        }

        // A normal row's velocity bias and gamma = K impulseScale / massScale, the compliance the
        // soft row adds to the block's diagonal (ContactSolver.Solve).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Terms(Vector<float> s, Vector<float> k, Vector<float> inverseStep, Vector<float> maxPush, Vector<float> rate, Vector<float> massScale,
            Vector<float> impulseScale, bool useBias, out Vector<float> bias, out Vector<float> gamma)
        {
            var speculative = Vector.GreaterThan(s, Vector<float>.Zero);
            if (useBias)
            {
                bias = WideVector3.Select(speculative, s * inverseStep, Vector.Max(rate * s, maxPush));
                Vector<float> ms = WideVector3.Select(speculative, Vector<float>.One, massScale);
                Vector<float> @is = WideVector3.Select(speculative, Vector<float>.Zero, impulseScale);
                gamma = WideVector3.Select(Vector.GreaterThan(@is, Vector<float>.Zero), k * @is / ms, Vector<float>.Zero);
            }
            else
            {
                bias = WideVector3.Select(speculative, s * inverseStep, Vector<float>.Zero);
                gamma = Vector<float>.Zero;
            }
        }

        // The block pair of slots bit1/bit2: returns the lanes' bits of the slots that carry
        // load for the first time in this step (and sets them in loaded).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<int> SolvePair(ref WidePoint p1, ref WidePoint p2, Vector<float> k11, Vector<float> k12, Vector<float> k22, int bit1, int bit2,
            in WideVector3 n, Vector<float> bias1, Vector<float> gamma1, Vector<float> bias2, Vector<float> gamma2,
            ref Vector<int> loaded, out Vector<float> vn1, out Vector<float> vn2, ref BodyLanes l)
        {
            Vector<float> zero = Vector<float>.Zero;

            Vector<float> a1 = p1.Impulse, a2 = p2.Impulse;
            // RowVelocity of both rows, their shared linear term n . (vB - vA) once.
            WideVector3 dv = l.VB;
            dv.Subtract(l.VA);
            Vector<float> linearVn = WideVector3.Dot(n, dv);
            vn1 = linearVn + WideVector3.Dot(p1.AngularB, l.WB) - WideVector3.Dot(p1.AngularA, l.WA);
            vn2 = linearVn + WideVector3.Dot(p2.AngularB, l.WB) - WideVector3.Dot(p2.AngularA, l.WA);
            Vector<float> A11 = k11 + gamma1, A22 = k22 + gamma2, A12 = k12;
            Vector<float> b1 = vn1 + bias1 - (k11 * a1 + k12 * a2);
            Vector<float> b2 = vn2 + bias2 - (k12 * a1 + k22 * a2);

            // The four cases of the 2x2 LCP, each checked per lane; the first that holds wins.
            Vector<float> det = A11 * A22 - A12 * A12;
            Vector<float> invDet = WideVector3.Select(Vector.Equals(det, zero), zero, Vector<float>.One / det);
            Vector<float> c1x1 = -(A22 * b1 - A12 * b2) * invDet;
            Vector<float> c1x2 = -(A11 * b2 - A12 * b1) * invDet;
            var ok1 = Vector.BitwiseAnd(Vector.GreaterThanOrEqual(c1x1, zero), Vector.GreaterThanOrEqual(c1x2, zero));
            Vector<float> x1 = c1x1, x2 = c1x2;
            // Both points pushing in every lane (resting stacks, nearly always): the other cases
            // cannot win, and their two divisions and eight selects are skipped.
            if (!Vector.EqualsAll(ok1, new Vector<int>(-1)))
            {
                Vector<float> c2x1 = -b1 / A11;
                var ok2 = Vector.BitwiseAnd(Vector.GreaterThanOrEqual(c2x1, zero), Vector.GreaterThanOrEqual(A12 * c2x1 + b2, zero));
                Vector<float> c3x2 = -b2 / A22;
                var ok3 = Vector.BitwiseAnd(Vector.GreaterThanOrEqual(c3x2, zero), Vector.GreaterThanOrEqual(A12 * c3x2 + b1, zero));
                var ok4 = Vector.BitwiseAnd(Vector.GreaterThanOrEqual(b1, zero), Vector.GreaterThanOrEqual(b2, zero));
                // No case holding (round-off only): the impulses stay.
                x1 = WideVector3.Select(ok4, zero, a1);
                x2 = WideVector3.Select(ok4, zero, a2);
                x1 = WideVector3.Select(ok3, zero, x1);
                x2 = WideVector3.Select(ok3, c3x2, x2);
                x1 = WideVector3.Select(ok2, c2x1, x1);
                x2 = WideVector3.Select(ok2, zero, x2);
                x1 = WideVector3.Select(ok1, c1x1, x1);
                x2 = WideVector3.Select(ok1, c1x2, x2);
            }

            Vector<float> d1 = x1 - a1, d2 = x2 - a2;
            p1.Impulse = x1;
            p2.Impulse = x2;
            var pressed = Vector.BitwiseOr(Vector.BitwiseAnd(Vector.GreaterThan(x1, zero), new Vector<int>(bit1)),
                Vector.BitwiseAnd(Vector.GreaterThan(x2, zero), new Vector<int>(bit2)));
            Vector<int> first = Vector.AndNot(pressed, loaded);
            loaded = Vector.BitwiseOr(loaded, pressed);

            WideVector3 linear = WideVector3.Scale(n, d1 + d2);
            WideVector3 angularA = WideVector3.Scale(p1.AngularA, d1);
            angularA.AddScaled(p2.AngularA, d2);
            WideVector3 angularB = WideVector3.Scale(p1.AngularB, d1);
            angularB.AddScaled(p2.AngularB, d2);
            Apply(linear, angularA, angularB, ref l);
            return first;
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        static void RefreshApproach(ref WideContact w, ref WideImpact impact, SolverBody[] bodies, int[] laneBodies, int groupOffset, ref BodyLanes l)
        {
            if (Vector.EqualsAll(impact.Restitution, Vector<float>.Zero)) return;
            WideBodies.Gather(bodies, laneBodies, groupOffset, ref l, false, false);
            Refresh(w.P0, ref impact.P0, w.Loaded, 1, w.Normal, l);
            Refresh(w.P1, ref impact.P1, w.Loaded, 2, w.Normal, l);
            Refresh(w.P2, ref impact.P2, w.Loaded, 4, w.Normal, l);
            Refresh(w.P3, ref impact.P3, w.Loaded, 8, w.Normal, l);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<int> IsLoaded(Vector<int> loaded, int bit) => Vector.Equals(Vector.BitwiseAnd(loaded, new Vector<int>(bit)), new Vector<int>(bit));

        static void Refresh(in WidePoint p, ref WideImpactPoint i, Vector<int> loaded, int bit, in WideVector3 n, in BodyLanes l)
        {
            i.RelativeVelocity = WideVector3.Select(IsLoaded(loaded, bit), i.RelativeVelocity, RowVelocity(p.AngularA, p.AngularB, n, l));
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        static void ApplyRestitution(ref WideContact w, ref WideImpact impact, SolverBody[] bodies, int[] laneBodies, int groupOffset, float threshold, ref BodyLanes l)
        {
            if (Vector.EqualsAll(impact.Restitution, Vector<float>.Zero)) return;
            WideBodies.Gather(bodies, laneBodies, groupOffset, ref l, true, false);
            var limit = new Vector<float>(-threshold);
            Restitute(ref w.P0, impact.P0, impact.Restitution, w.Loaded, 1, w.Normal, limit, ref l);
            Restitute(ref w.P1, impact.P1, impact.Restitution, w.Loaded, 2, w.Normal, limit, ref l);
            Restitute(ref w.P2, impact.P2, impact.Restitution, w.Loaded, 4, w.Normal, limit, ref l);
            Restitute(ref w.P3, impact.P3, impact.Restitution, w.Loaded, 8, w.Normal, limit, ref l);
            WideBodies.Scatter(bodies, laneBodies, groupOffset, ref l);
        }

        static void Restitute(ref WidePoint p, in WideImpactPoint i, Vector<float> e, Vector<int> loaded, int bit, in WideVector3 n,
            Vector<float> limit, ref BodyLanes l)
        {
            Vector<float> zero = Vector<float>.Zero;
            // As ContactSolver.ApplyRestitution: impacts of this substep only (nothing applied
            // before). A restitution impulse is never negative, so the point stays loaded.
            var active = Vector.BitwiseAnd(Vector.BitwiseAnd(Vector.LessThanOrEqual(i.RelativeVelocity, limit), Vector.Equals(i.Applied, zero)),
                Vector.BitwiseAnd(IsLoaded(loaded, bit), Vector.GreaterThan(e, zero)));
            if (Vector.EqualsAll(active, Vector<int>.Zero)) return;
            Vector<float> vn = RowVelocity(p.AngularA, p.AngularB, n, l);
            Vector<float> old = p.Impulse;
            Vector<float> total = Vector.Max(old - i.EffectiveMass * (vn + e * i.RelativeVelocity), zero);
            total = WideVector3.Select(active, total, old);
            p.Impulse = total;
            Vector<float> d = total - old;
            Apply(WideVector3.Scale(n, d), WideVector3.Scale(p.AngularA, d), WideVector3.Scale(p.AngularB, d), ref l);
        }

        /// <summary>What a substep applied: the point slots' impulses now (see SolverContext.AccumulateApplied).</summary>
        public static void Accumulate(in WideContact w, ref WideImpact impact)
        {
            Accumulate(w.P0.Impulse, ref impact.P0);
            Accumulate(w.P1.Impulse, ref impact.P1);
            Accumulate(w.P2.Impulse, ref impact.P2);
            Accumulate(w.P3.Impulse, ref impact.P3);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Accumulate(Vector<float> impulse, ref WideImpactPoint i)
        {
            i.Applied += impulse;
            i.LastSubstep = impulse;
        }

        /// <summary>
        /// Writes a group's impulses back into its manifolds (per step: times <paramref name="scale"/>);
        /// <paramref name="laneManifolds"/> names each lane's manifold (-1: none).
        /// </summary>
        public static void Store(in WideContact w, in WideImpact impact, int[] laneSlots, int[] laneManifolds, int groupOffset,
            ContactManifold[] manifolds, float scale)
        {
            int width = Width;
            float share = scale / 4f;
            for (int lane = 0; lane < width; lane++)
            {
                int at = groupOffset + lane;
                int mi = laneManifolds[at];
                if (mi < 0) continue;
                ref ContactManifold m = ref manifolds[mi];
                float f1 = w.FrictionImpulse1.GetElement(lane), f2 = w.FrictionImpulse2.GetElement(lane);
                StorePoint(ref ContactManifold.Point(ref m, laneSlots[4 * at]), w.P0, impact.P0, lane, scale, share, f1, f2);
                StorePoint(ref ContactManifold.Point(ref m, laneSlots[4 * at + 1]), w.P1, impact.P1, lane, scale, share, f1, f2);
                StorePoint(ref ContactManifold.Point(ref m, laneSlots[4 * at + 2]), w.P2, impact.P2, lane, scale, share, f1, f2);
                StorePoint(ref ContactManifold.Point(ref m, laneSlots[4 * at + 3]), w.P3, impact.P3, lane, scale, share, f1, f2);
                m.RollingImpulse = scale * w.TwistImpulse.GetElement(lane) * w.Normal.Get(lane);
            }
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void StorePoint(ref ContactPoint mp, in WidePoint p, in WideImpactPoint i, int lane, float scale, float share, float f1, float f2)
        {
            float impulse = p.Impulse.GetElement(lane);
            mp.NormalImpulse = scale * impulse;
            mp.AppliedImpulse = i.Applied.GetElement(lane) + impulse - i.LastSubstep.GetElement(lane);
            mp.TangentImpulse1 = share * f1;
            mp.TangentImpulse2 = share * f2;
            mp.RelativeNormalVelocity = i.RelativeVelocity.GetElement(lane);
        }
    }
}
#endif
