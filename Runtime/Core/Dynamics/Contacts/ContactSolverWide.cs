#if NET
using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    /// <summary>One normal row of a lane group (see <see cref="ContactSolverWide"/>).</summary>
    internal struct WideRow
    {
        public WideVector3 AngularA, AngularB, VelocityA, VelocityB;
        public Vector<float> EffectiveMass, Impulse;
    }

    /// <summary>One point slot of a lane group: its normal row and what restitution needs.</summary>
    internal struct WidePoint
    {
        public WideRow Normal;
        public Vector<float> Separation, RelativeVelocity, MaxNormalImpulse;
        public Vector<float> Applied, LastSubstep;   // see ContactConstraintPoint
    }

    /// <summary>
    /// Vector&lt;float&gt;.Count four-point manifolds of one colour, lane by lane: the data of
    /// <see cref="ContactConstraint"/> and its points transposed so that every arithmetic
    /// operation of a pass works on all lanes at once. The point slots are ordered by block
    /// pair: slots 0-1 are the first pair, 2-3 the second.
    /// </summary>
    internal struct WideContact
    {
        public WidePoint P0, P1, P2, P3;
        public Vector<float> K11a, K12a, K22a, K11b, K12b, K22b;
        public WideVector3 Normal, Tangent1, Tangent2;
        public Vector<float> InvMassA, InvMassB, Friction, Restitution;
        public Vector<float> BiasRate, MassScale, ImpulseScale;
        public WideRow Friction1, Friction2;
        public WideVector3 TwistVelocityA, TwistVelocityB;
        public Vector<float> TwistMass, TwistImpulse, TwistRadius;
    }

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
    internal static class ContactSolverWide
    {
        public static int Width => Vector<float>.Count;

        /// <summary>True for a manifold the wide path can take.</summary>
        public static bool Accepts(in ContactConstraint c) =>
            Vector.IsHardwareAccelerated && c.PointCount == 4 && c.Block0.IsUsed && c.Block1.IsUsed && c.RollingFriction == 0;

        /// <summary>
        /// Transposes the prepared constraints <paramref name="source"/>[i] into lanes of
        /// <paramref name="w"/>; unused lanes get the fixed body and inert rows.
        /// </summary>
        public static void Load(ref WideContact w, int[] laneBodies, int groupOffset, ReadOnlySpan<int> source,
            ContactConstraint[] contacts, ContactConstraintPoint[] points, SolverBody[] bodies, int[] laneSlots)
        {
            int width = Width;
            // Every field of a used lane is written below: only padding lanes need the clear.
            if (source.Length < width) w = default;
            for (int lane = 0; lane < width; lane++)
            {
                int at = groupOffset + lane;
                if (lane >= source.Length)
                {
                    laneBodies[2 * at] = 0;
                    laneBodies[2 * at + 1] = 0;
                    laneSlots[4 * at] = laneSlots[4 * at + 1] = laneSlots[4 * at + 2] = laneSlots[4 * at + 3] = -1;
                    continue;
                }
                ref ContactConstraint c = ref contacts[source[lane]];
                laneBodies[2 * at] = c.BodyA;
                laneBodies[2 * at + 1] = c.BodyB;
                LoadPoint(ref w.P0, lane, points[c.Block0.I]);
                LoadPoint(ref w.P1, lane, points[c.Block0.J]);
                LoadPoint(ref w.P2, lane, points[c.Block1.I]);
                LoadPoint(ref w.P3, lane, points[c.Block1.J]);
                laneSlots[4 * at] = c.Block0.I;
                laneSlots[4 * at + 1] = c.Block0.J;
                laneSlots[4 * at + 2] = c.Block1.I;
                laneSlots[4 * at + 3] = c.Block1.J;
                WideVector3.Lane(ref w.K11a, lane) = c.Block0.K11;
                WideVector3.Lane(ref w.K12a, lane) = c.Block0.K12;
                WideVector3.Lane(ref w.K22a, lane) = c.Block0.K22;
                WideVector3.Lane(ref w.K11b, lane) = c.Block1.K11;
                WideVector3.Lane(ref w.K12b, lane) = c.Block1.K12;
                WideVector3.Lane(ref w.K22b, lane) = c.Block1.K22;
                w.Normal.Set(lane, c.Normal);
                w.Tangent1.Set(lane, c.Tangent1);
                w.Tangent2.Set(lane, c.Tangent2);
                WideVector3.Lane(ref w.InvMassA, lane) = c.InvMassA;
                WideVector3.Lane(ref w.InvMassB, lane) = c.InvMassB;
                WideVector3.Lane(ref w.Friction, lane) = c.Friction;
                WideVector3.Lane(ref w.Restitution, lane) = c.Restitution;
                WideVector3.Lane(ref w.BiasRate, lane) = c.Softness.BiasRate;
                WideVector3.Lane(ref w.MassScale, lane) = c.Softness.MassScale;
                WideVector3.Lane(ref w.ImpulseScale, lane) = c.Softness.ImpulseScale;
                LoadRow(ref w.Friction1, lane, c.Friction1);
                LoadRow(ref w.Friction2, lane, c.Friction2);
                w.TwistVelocityA.Set(lane, bodies[c.BodyA].InverseInertia * c.Normal);
                w.TwistVelocityB.Set(lane, bodies[c.BodyB].InverseInertia * c.Normal);
                WideVector3.Lane(ref w.TwistMass, lane) = c.TwistMass;
                WideVector3.Lane(ref w.TwistImpulse, lane) = c.TwistImpulse;
                WideVector3.Lane(ref w.TwistRadius, lane) = c.TwistRadius;
            }
        }

        static void LoadRow(ref WideRow r, int lane, in ContactRow s)
        {
            r.AngularA.Set(lane, s.AngularA);
            r.AngularB.Set(lane, s.AngularB);
            r.VelocityA.Set(lane, s.VelocityA);
            r.VelocityB.Set(lane, s.VelocityB);
            WideVector3.Lane(ref r.EffectiveMass, lane) = s.EffectiveMass;
            WideVector3.Lane(ref r.Impulse, lane) = s.Impulse;
        }

        static void LoadPoint(ref WidePoint p, int lane, in ContactConstraintPoint s)
        {
            LoadRow(ref p.Normal, lane, s.Normal);
            WideVector3.Lane(ref p.Separation, lane) = s.Separation;
            WideVector3.Lane(ref p.RelativeVelocity, lane) = s.RelativeVelocity;
            WideVector3.Lane(ref p.MaxNormalImpulse, lane) = s.MaxNormalImpulse;
            WideVector3.Lane(ref p.Applied, lane) = 0;
            WideVector3.Lane(ref p.LastSubstep, lane) = 0;
        }

        /// <summary>The bodies of a group in lanes: velocities and (for the separation update) motion so far.</summary>
        struct Lanes
        {
            public WideVector3 VA, WA, VB, WB, DpA, DpB, DThetaA, DThetaB;
            // The floats beside the velocities in SolverBody (inverse mass, the dynamic flag),
            // written back unchanged by the transposing scatter.
            public Vector<float> PadVA, PadWA, PadVB, PadWB;
        }

        static void Gather(SolverBody[] bodies, int[] laneBodies, int groupOffset, out Lanes l, bool motion)
        {
            if (SolverBodyLanes.IsSupported)
            {
                GatherSide(bodies, laneBodies, 2 * groupOffset, motion, out l.VA, out l.PadVA, out l.WA, out l.PadWA, out l.DpA, out l.DThetaA);
                GatherSide(bodies, laneBodies, 2 * groupOffset + 1, motion, out l.VB, out l.PadVB, out l.WB, out l.PadWB, out l.DpB, out l.DThetaB);
                return;
            }
            l = default;
            int width = Width;
            for (int lane = 0; lane < width; lane++)
            {
                ref SolverBody a = ref bodies[laneBodies[2 * (groupOffset + lane)]];
                ref SolverBody b = ref bodies[laneBodies[2 * (groupOffset + lane) + 1]];
                l.VA.Set(lane, a.LinearVelocity);
                l.WA.Set(lane, a.AngularVelocity);
                l.VB.Set(lane, b.LinearVelocity);
                l.WB.Set(lane, b.AngularVelocity);
                if (!motion) continue;
                l.DpA.Set(lane, a.DeltaPosition);
                l.DpB.Set(lane, b.DeltaPosition);
                l.DThetaA.Set(lane, a.DeltaAngle);
                l.DThetaB.Set(lane, b.DeltaAngle);
            }
        }

        // One side (A: at = 2 groupOffset, B: at + 1) of the eight lanes, by transposes.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void GatherSide(SolverBody[] bodies, int[] laneBodies, int at, bool motion,
            out WideVector3 v, out Vector<float> padV, out WideVector3 w, out Vector<float> padW, out WideVector3 dp, out WideVector3 dTheta)
        {
            ref float b0 = ref SolverBodyLanes.Body(bodies, laneBodies, at);
            ref float b1 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 2);
            ref float b2 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 4);
            ref float b3 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 6);
            ref float b4 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 8);
            ref float b5 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 10);
            ref float b6 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 12);
            ref float b7 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 14);
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Linear,
                out Vector<float> vx, out Vector<float> vy, out Vector<float> vz, out padV);
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Angular,
                out Vector<float> wx, out Vector<float> wy, out Vector<float> wz, out padW);
            v = new WideVector3 { X = vx, Y = vy, Z = vz };
            w = new WideVector3 { X = wx, Y = wy, Z = wz };
            if (!motion)
            {
                dp = default;
                dTheta = default;
                return;
            }
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Displacement,
                out _, out Vector<float> px, out Vector<float> py, out Vector<float> pz);
            SolverBodyLanes.Load(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, SolverBodyLanes.Rotation,
                out Vector<float> qx, out Vector<float> qy, out Vector<float> qz, out Vector<float> qw);
            dp = new WideVector3 { X = px, Y = py, Z = pz };
            // SolverBody.DeltaAngle, lane by lane: 2 x the vector part, sign chosen by w.
            Vector<float> twice = Vector.ConditionalSelect(Vector.LessThan(qw, Vector<float>.Zero), new Vector<float>(-2f), new Vector<float>(2f));
            dTheta = new WideVector3 { X = qx * twice, Y = qy * twice, Z = qz * twice };
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void ScatterSide(SolverBody[] bodies, int[] laneBodies, int at, in WideVector3 v, Vector<float> padV, in WideVector3 w, Vector<float> padW)
        {
            // Only dynamic bodies are written (the flag is the angular block's fourth float).
            int write = (int)Vector256.ExtractMostSignificantBits(
                ~Vector256.Equals(Vector.AsVectorInt32(padW).AsVector256(), Vector256<int>.Zero));
            if (write == 0) return;
            ref float b0 = ref SolverBodyLanes.Body(bodies, laneBodies, at);
            ref float b1 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 2);
            ref float b2 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 4);
            ref float b3 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 6);
            ref float b4 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 8);
            ref float b5 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 10);
            ref float b6 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 12);
            ref float b7 = ref SolverBodyLanes.Body(bodies, laneBodies, at + 14);
            SolverBodyLanes.Store(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, write, SolverBodyLanes.Linear, v.X, v.Y, v.Z, padV);
            SolverBodyLanes.Store(ref b0, ref b1, ref b2, ref b3, ref b4, ref b5, ref b6, ref b7, write, SolverBodyLanes.Angular, w.X, w.Y, w.Z, padW);
        }

        static void Scatter(SolverBody[] bodies, int[] laneBodies, int groupOffset, ref Lanes l)
        {
            if (SolverBodyLanes.IsSupported)
            {
                ScatterSide(bodies, laneBodies, 2 * groupOffset, l.VA, l.PadVA, l.WA, l.PadWA);
                ScatterSide(bodies, laneBodies, 2 * groupOffset + 1, l.VB, l.PadVB, l.WB, l.PadWB);
                return;
            }
            int width = Width;
            for (int lane = 0; lane < width; lane++)
            {
                ref SolverBody a = ref bodies[laneBodies[2 * (groupOffset + lane)]];
                ref SolverBody b = ref bodies[laneBodies[2 * (groupOffset + lane) + 1]];
                if (a.IsDynamic != 0)
                {
                    a.LinearVelocity = Get(ref l.VA, lane);
                    a.AngularVelocity = Get(ref l.WA, lane);
                }
                if (b.IsDynamic != 0)
                {
                    b.LinearVelocity = Get(ref l.VB, lane);
                    b.AngularVelocity = Get(ref l.WB, lane);
                }
            }
        }

        static Vector3 Get(ref WideVector3 v, int lane) =>
            new Vector3(WideVector3.Lane(ref v.X, lane), WideVector3.Lane(ref v.Y, lane), WideVector3.Lane(ref v.Z, lane));

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<float> RowVelocity(in WideRow r, in WideVector3 d, in Lanes l)
        {
            WideVector3 dv = l.VB;
            dv.Subtract(l.VA);
            return WideVector3.Dot(d, dv) + WideVector3.Dot(r.AngularB, l.WB) - WideVector3.Dot(r.AngularA, l.WA);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void ApplyNormal(in WideContact w, in WideRow r, Vector<float> impulse, ref Lanes l)
        {
            l.VA.SubtractScaled(w.Normal, w.InvMassA * impulse);
            l.WA.SubtractScaled(r.VelocityA, impulse);
            l.VB.AddScaled(w.Normal, w.InvMassB * impulse);
            l.WB.AddScaled(r.VelocityB, impulse);
        }

        // The passes run over ranges of groups [first, end): one method call per range keeps
        // the lane registers' stack home (zeroed on entry) to one per call, not one per group.

        /// <summary>The warm start of groups [first, end).</summary>
        public static void WarmStart(WideContact[] groups, int first, int end, SolverBody[] bodies, int[] laneBodies)
        {
            for (int g = first; g < end; g++) WarmStart(ref groups[g], bodies, laneBodies, g * Width);
        }

        /// <summary>One pass (biased or relaxing) over groups [first, end).</summary>
        public static void Solve(WideContact[] groups, int first, int end, SolverBody[] bodies, int[] laneBodies, float invH, float maxPushSpeed, bool useBias)
        {
            for (int g = first; g < end; g++) Solve(ref groups[g], bodies, laneBodies, g * Width, invH, maxPushSpeed, useBias);
        }

        /// <summary>ContactSolver.RefreshApproach for groups [first, end).</summary>
        public static void RefreshApproach(WideContact[] groups, int first, int end, SolverBody[] bodies, int[] laneBodies)
        {
            for (int g = first; g < end; g++) RefreshApproach(ref groups[g], bodies, laneBodies, g * Width);
        }

        /// <summary>The restitution pass of groups [first, end).</summary>
        public static void ApplyRestitution(WideContact[] groups, int first, int end, SolverBody[] bodies, int[] laneBodies, float threshold)
        {
            for (int g = first; g < end; g++) ApplyRestitution(ref groups[g], bodies, laneBodies, g * Width, threshold);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void WarmStart(ref WideContact w, SolverBody[] bodies, int[] laneBodies, int groupOffset)
        {
            Gather(bodies, laneBodies, groupOffset, out Lanes l, false);
            WarmRow(w, w.P0.Normal, w.Normal, ref l);
            WarmRow(w, w.P1.Normal, w.Normal, ref l);
            WarmRow(w, w.P2.Normal, w.Normal, ref l);
            WarmRow(w, w.P3.Normal, w.Normal, ref l);
            WarmRow(w, w.Friction1, w.Tangent1, ref l);
            WarmRow(w, w.Friction2, w.Tangent2, ref l);
            l.WA.SubtractScaled(w.TwistVelocityA, w.TwistImpulse);
            l.WB.AddScaled(w.TwistVelocityB, w.TwistImpulse);
            Scatter(bodies, laneBodies, groupOffset, ref l);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void WarmRow(in WideContact w, in WideRow r, in WideVector3 d, ref Lanes l)
        {
            l.VA.SubtractScaled(d, w.InvMassA * r.Impulse);
            l.WA.SubtractScaled(r.VelocityA, r.Impulse);
            l.VB.AddScaled(d, w.InvMassB * r.Impulse);
            l.WB.AddScaled(r.VelocityB, r.Impulse);
        }

        // One pass (biased or relaxing) over a group; the same rows, in the same order, as ContactSolver.Solve.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Solve(ref WideContact w, SolverBody[] bodies, int[] laneBodies, int groupOffset, float invH, float maxPushSpeed, bool useBias)
        {
            Gather(bodies, laneBodies, groupOffset, out Lanes l, true);
            WideVector3 dp = l.DpB;
            dp.Subtract(l.DpA);
            Vector<float> drift = WideVector3.Dot(w.Normal, dp);
            var inverseStep = new Vector<float>(invH);
            var maxPush = new Vector<float>(-maxPushSpeed);
            SolvePair(ref w, ref w.P0, ref w.P1, w.K11a, w.K12a, w.K22a, drift, inverseStep, maxPush, useBias, ref l);
            SolvePair(ref w, ref w.P2, ref w.P3, w.K11b, w.K12b, w.K22b, drift, inverseStep, maxPush, useBias, ref l);

            Vector<float> total = w.P0.Normal.Impulse + w.P1.Normal.Impulse + w.P2.Normal.Impulse + w.P3.Normal.Impulse;
            Vector<float> maxFriction = w.Friction * total;
            Vector<float> old1 = w.Friction1.Impulse, old2 = w.Friction2.Impulse;
            Vector<float> new1 = old1 - w.Friction1.EffectiveMass * RowVelocity(w.Friction1, w.Tangent1, l);
            Vector<float> new2 = old2 - w.Friction2.EffectiveMass * RowVelocity(w.Friction2, w.Tangent2, l);
            Vector<float> len2 = new1 * new1 + new2 * new2;
            Vector<float> scale = Vector.ConditionalSelect(Vector.GreaterThan(len2, maxFriction * maxFriction),
                maxFriction / Vector.SquareRoot(len2), Vector<float>.One);
            new1 *= scale;
            new2 *= scale;
            w.Friction1.Impulse = new1;
            w.Friction2.Impulse = new2;
            Vector<float> d1 = new1 - old1, d2 = new2 - old2;
            l.VA.SubtractScaled(w.Tangent1, w.InvMassA * d1);
            l.VA.SubtractScaled(w.Tangent2, w.InvMassA * d2);
            l.WA.SubtractScaled(w.Friction1.VelocityA, d1);
            l.WA.SubtractScaled(w.Friction2.VelocityA, d2);
            l.VB.AddScaled(w.Tangent1, w.InvMassB * d1);
            l.VB.AddScaled(w.Tangent2, w.InvMassB * d2);
            l.WB.AddScaled(w.Friction1.VelocityB, d1);
            l.WB.AddScaled(w.Friction2.VelocityB, d2);

            Vector<float> maxTwist = maxFriction * w.TwistRadius;
            WideVector3 dw = l.WB;
            dw.Subtract(l.WA);
            Vector<float> oldTwist = w.TwistImpulse;
            Vector<float> twist = Vector.Min(Vector.Max(oldTwist - w.TwistMass * WideVector3.Dot(w.Normal, dw), -maxTwist), maxTwist);
            w.TwistImpulse = twist;
            Vector<float> dt = twist - oldTwist;
            l.WA.SubtractScaled(w.TwistVelocityA, dt);
            l.WB.AddScaled(w.TwistVelocityB, dt);
            Scatter(bodies, laneBodies, groupOffset, ref l);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void Terms(Vector<float> s, in WideContact w, Vector<float> inverseStep, Vector<float> maxPush, bool useBias,
            out Vector<float> bias, out Vector<float> massScale, out Vector<float> impulseScale)
        {
            var speculative = Vector.GreaterThan(s, Vector<float>.Zero);
            if (useBias)
            {
                bias = Vector.ConditionalSelect(speculative, s * inverseStep, Vector.Max(w.BiasRate * s, maxPush));
                massScale = Vector.ConditionalSelect(speculative, Vector<float>.One, w.MassScale);
                impulseScale = Vector.ConditionalSelect(speculative, Vector<float>.Zero, w.ImpulseScale);
            }
            else
            {
                bias = Vector.ConditionalSelect(speculative, s * inverseStep, Vector<float>.Zero);
                massScale = Vector<float>.One;
                impulseScale = Vector<float>.Zero;
            }
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void SolvePair(ref WideContact w, ref WidePoint p1, ref WidePoint p2, Vector<float> k11, Vector<float> k12, Vector<float> k22,
            Vector<float> drift, Vector<float> inverseStep, Vector<float> maxPush, bool useBias, ref Lanes l)
        {
            Vector<float> s1 = p1.Separation + drift + WideVector3.Dot(l.DThetaB, p1.Normal.AngularB) - WideVector3.Dot(l.DThetaA, p1.Normal.AngularA);
            Vector<float> s2 = p2.Separation + drift + WideVector3.Dot(l.DThetaB, p2.Normal.AngularB) - WideVector3.Dot(l.DThetaA, p2.Normal.AngularA);
            Terms(s1, w, inverseStep, maxPush, useBias, out Vector<float> bias1, out Vector<float> ms1, out Vector<float> is1);
            Terms(s2, w, inverseStep, maxPush, useBias, out Vector<float> bias2, out Vector<float> ms2, out Vector<float> is2);
            Vector<float> zero = Vector<float>.Zero;
            Vector<float> gamma1 = Vector.ConditionalSelect(Vector.GreaterThan(is1, zero), k11 * is1 / ms1, zero);
            Vector<float> gamma2 = Vector.ConditionalSelect(Vector.GreaterThan(is2, zero), k22 * is2 / ms2, zero);

            Vector<float> a1 = p1.Normal.Impulse, a2 = p2.Normal.Impulse;
            Vector<float> vn1 = RowVelocity(p1.Normal, w.Normal, l);
            Vector<float> vn2 = RowVelocity(p2.Normal, w.Normal, l);
            Vector<float> A11 = k11 + gamma1, A22 = k22 + gamma2, A12 = k12;
            Vector<float> b1 = vn1 + bias1 - (k11 * a1 + k12 * a2);
            Vector<float> b2 = vn2 + bias2 - (k12 * a1 + k22 * a2);

            // The four cases of the 2x2 LCP, each checked per lane; the first that holds wins.
            Vector<float> det = A11 * A22 - A12 * A12;
            Vector<float> invDet = Vector.ConditionalSelect(Vector.Equals(det, zero), zero, Vector<float>.One / det);
            Vector<float> c1x1 = -(A22 * b1 - A12 * b2) * invDet;
            Vector<float> c1x2 = -(A11 * b2 - A12 * b1) * invDet;
            var ok1 = Vector.BitwiseAnd(Vector.GreaterThanOrEqual(c1x1, zero), Vector.GreaterThanOrEqual(c1x2, zero));
            Vector<float> c2x1 = -b1 / A11;
            var ok2 = Vector.BitwiseAnd(Vector.GreaterThanOrEqual(c2x1, zero), Vector.GreaterThanOrEqual(A12 * c2x1 + b2, zero));
            Vector<float> c3x2 = -b2 / A22;
            var ok3 = Vector.BitwiseAnd(Vector.GreaterThanOrEqual(c3x2, zero), Vector.GreaterThanOrEqual(A12 * c3x2 + b1, zero));
            var ok4 = Vector.BitwiseAnd(Vector.GreaterThanOrEqual(b1, zero), Vector.GreaterThanOrEqual(b2, zero));
            // No case holding (round-off only): the impulses stay.
            Vector<float> x1 = Vector.ConditionalSelect(ok4, zero, a1);
            Vector<float> x2 = Vector.ConditionalSelect(ok4, zero, a2);
            x1 = Vector.ConditionalSelect(ok3, zero, x1);
            x2 = Vector.ConditionalSelect(ok3, c3x2, x2);
            x1 = Vector.ConditionalSelect(ok2, c2x1, x1);
            x2 = Vector.ConditionalSelect(ok2, zero, x2);
            x1 = Vector.ConditionalSelect(ok1, c1x1, x1);
            x2 = Vector.ConditionalSelect(ok1, c1x2, x2);

            Vector<float> d1 = x1 - a1, d2 = x2 - a2;
            p1.Normal.Impulse = x1;
            p2.Normal.Impulse = x2;
            // The approach speed of the (sub)step a point first carries load (RecordImpact).
            var first1 = Vector.BitwiseAnd(Vector.GreaterThan(x1, p1.MaxNormalImpulse), Vector.Equals(p1.MaxNormalImpulse, zero));
            var first2 = Vector.BitwiseAnd(Vector.GreaterThan(x2, p2.MaxNormalImpulse), Vector.Equals(p2.MaxNormalImpulse, zero));
            p1.RelativeVelocity = Vector.ConditionalSelect(first1, Vector.Max(vn1, p1.RelativeVelocity), p1.RelativeVelocity);
            p2.RelativeVelocity = Vector.ConditionalSelect(first2, Vector.Max(vn2, p2.RelativeVelocity), p2.RelativeVelocity);
            p1.MaxNormalImpulse = Vector.Max(p1.MaxNormalImpulse, x1);
            p2.MaxNormalImpulse = Vector.Max(p2.MaxNormalImpulse, x2);
            ApplyNormal(w, p1.Normal, d1, ref l);
            ApplyNormal(w, p2.Normal, d2, ref l);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void RefreshApproach(ref WideContact w, SolverBody[] bodies, int[] laneBodies, int groupOffset)
        {
            if (Vector.EqualsAll(w.Restitution, Vector<float>.Zero)) return;
            Gather(bodies, laneBodies, groupOffset, out Lanes l, false);
            Refresh(w, ref w.P0, l);
            Refresh(w, ref w.P1, l);
            Refresh(w, ref w.P2, l);
            Refresh(w, ref w.P3, l);
        }

        static void Refresh(in WideContact w, ref WidePoint p, in Lanes l)
        {
            var untouched = Vector.Equals(p.MaxNormalImpulse, Vector<float>.Zero);
            p.RelativeVelocity = Vector.ConditionalSelect(untouched, RowVelocity(p.Normal, w.Normal, l), p.RelativeVelocity);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void ApplyRestitution(ref WideContact w, SolverBody[] bodies, int[] laneBodies, int groupOffset, float threshold)
        {
            if (Vector.EqualsAll(w.Restitution, Vector<float>.Zero)) return;
            Gather(bodies, laneBodies, groupOffset, out Lanes l, false);
            var limit = new Vector<float>(-threshold);
            Restitute(ref w, ref w.P0, limit, ref l);
            Restitute(ref w, ref w.P1, limit, ref l);
            Restitute(ref w, ref w.P2, limit, ref l);
            Restitute(ref w, ref w.P3, limit, ref l);
            Scatter(bodies, laneBodies, groupOffset, ref l);
        }

        static void Restitute(ref WideContact w, ref WidePoint p, Vector<float> limit, ref Lanes l)
        {
            Vector<float> zero = Vector<float>.Zero;
            // As ContactSolver.ApplyRestitution: impacts of this substep only (nothing applied before).
            var active = Vector.BitwiseAnd(Vector.BitwiseAnd(Vector.LessThanOrEqual(p.RelativeVelocity, limit), Vector.Equals(p.Applied, zero)),
                Vector.BitwiseAnd(Vector.GreaterThan(p.MaxNormalImpulse, zero), Vector.GreaterThan(w.Restitution, zero)));
            if (Vector.EqualsAll(active, Vector<int>.Zero)) return;
            Vector<float> vn = RowVelocity(p.Normal, w.Normal, l);
            Vector<float> old = p.Normal.Impulse;
            Vector<float> total = Vector.Max(old - p.Normal.EffectiveMass * (vn + w.Restitution * p.RelativeVelocity), zero);
            total = Vector.ConditionalSelect(active, total, old);
            p.Normal.Impulse = total;
            p.MaxNormalImpulse = Vector.Max(p.MaxNormalImpulse, total);
            ApplyNormal(w, p.Normal, total - old, ref l);
        }

        /// <summary>Writes a group's impulses back into its manifolds (per step: times <paramref name="scale"/>).</summary>
        public static void Store(in WideContact w, int[] laneSlots, int groupOffset, ReadOnlySpan<int> source, ContactConstraint[] contacts,
            ContactConstraintPoint[] points, ContactManifold[] manifolds, float scale)
        {
            for (int lane = 0; lane < source.Length; lane++)
            {
                ref ContactConstraint c = ref contacts[source[lane]];
                ref ContactManifold m = ref manifolds[c.Manifold];
                float share = scale / 4f;
                float f1 = w.Friction1.Impulse.GetElement(lane), f2 = w.Friction2.Impulse.GetElement(lane);
                for (int k = 0; k < 4; k++)
                {
                    ref readonly WidePoint wp = ref k == 0 ? ref w.P0 : ref k == 1 ? ref w.P1 : ref k == 2 ? ref w.P2 : ref w.P3;
                    ref ContactPoint mp = ref ContactManifold.Point(ref m, points[laneSlots[4 * (groupOffset + lane) + k]].ManifoldPoint);
                    mp.NormalImpulse = scale * wp.Normal.Impulse.GetElement(lane);
                    mp.AppliedImpulse = wp.Applied.GetElement(lane) + wp.Normal.Impulse.GetElement(lane) - wp.LastSubstep.GetElement(lane);
                    mp.TangentImpulse1 = share * f1;
                    mp.TangentImpulse2 = share * f2;
                    mp.RelativeNormalVelocity = wp.RelativeVelocity.GetElement(lane);
                }
                m.RollingImpulse = scale * w.TwistImpulse.GetElement(lane) * c.Normal;
            }
        }
    }
}
#endif
