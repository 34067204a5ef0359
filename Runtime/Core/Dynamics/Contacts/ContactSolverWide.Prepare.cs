#if NET
using System.Numerics;
using System.Runtime.CompilerServices;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    internal static partial class ContactSolverWide
    {
        /// <summary>True for a manifold the wide path may take, before its block pairs are known.</summary>
        public static bool MayAccept(in ContactManifold m) => Vector.IsHardwareAccelerated && m.PointCount == 4 && m.RollingFriction == 0;

        /// <summary>A manifold's inputs in lanes (its points in manifold order).</summary>
        struct ManifoldLanes
        {
            public WideVector3 Normal;
            public Vector<float> Friction, Restitution, Twist, Tangent1, Tangent2;
            public WideVector3 AnchorA0, AnchorA1, AnchorA2, AnchorA3, AnchorB0, AnchorB1, AnchorB2, AnchorB3;
            public Vector<float> Separation0, Separation1, Separation2, Separation3, Impulse0, Impulse1, Impulse2, Impulse3;
        }

        /// <summary>
        /// <see cref="ContactSolver.Prepare"/> and <see cref="ContactBlockSolver.Prepare"/> for the
        /// four-point manifolds of groups [first, end), computed lane-wise straight into the
        /// groups: <paramref name="laneManifolds"/> names each lane's manifold (-1: padding) and
        /// <paramref name="laneBodies"/> its solver bodies. A lane whose block pairs are
        /// ill-conditioned is not taken: it is made inert (fixed bodies, no manifold) and its
        /// manifold index is written to <paramref name="rejected"/> from
        /// <paramref name="rejectedCount"/> on, for the scalar path. <paramref name="laneSlots"/>
        /// gets, per lane and slot, the point's index in its manifold. Returns true when some
        /// lane has restitution.
        /// </summary>
        public static bool Prepare(WideContact[] groups, WideImpact[] impacts, int first, int end, int[] laneManifolds, int[] laneBodies,
            int[] laneSlots, ContactManifold[] manifolds, SolverBody[] bodies, float warmScale, int[] rejected, ref int rejectedCount)
        {
            int width = Width;
            bool restitution = false;
            var warm = new Vector<float>(warmScale);
            BodyLanes l = default;
            for (int g = first; g < end; g++)
            {
                int offset = g * width;
                ManifoldLanes m = default;
                for (int lane = 0; lane < width; lane++)
                {
                    int mi = laneManifolds[offset + lane];
                    if (mi >= 0) LoadManifold(ref m, lane, ref manifolds[mi]);
                }
                WideBodies.Gather(bodies, laneBodies, offset, ref l, true, false);
                int reject = PrepareGroup(ref groups[g], ref impacts[g], m, l, warm, out Vector<int> far);
                restitution |= !Vector.EqualsAll(impacts[g].Restitution, Vector<float>.Zero);
                for (int lane = 0; lane < width; lane++)
                {
                    int at = offset + lane;
                    int f = far.GetElement(lane);
                    laneSlots[4 * at] = 0;
                    laneSlots[4 * at + 1] = f;
                    laneSlots[4 * at + 2] = f == 1 ? 2 : 1;
                    laneSlots[4 * at + 3] = f == 3 ? 2 : 3;
                    if ((reject & (1 << lane)) == 0 || laneManifolds[at] < 0) continue;
                    rejected[rejectedCount++] = laneManifolds[at];
                    laneManifolds[at] = -1;
                    laneBodies[2 * at] = laneBodies[2 * at + 1] = 0;
                    ClearLane(ref groups[g], ref impacts[g], lane);
                }
            }
            return restitution;
        }

        static void LoadManifold(ref ManifoldLanes w, int lane, ref ContactManifold m)
        {
            w.Normal.Set(lane, m.Normal);
            WideVector3.Lane(ref w.Friction, lane) = m.Friction;
            WideVector3.Lane(ref w.Restitution, lane) = m.Restitution;
            WideVector3.Lane(ref w.Twist, lane) = Vector3.Dot(m.RollingImpulse, m.Normal);
            // Sums in point order, as the scalar prepare takes them.
            float t1 = 0, t2 = 0;
            for (int i = 0; i < 4; i++)
            {
                ref ContactPoint p = ref ContactManifold.Point(ref m, i);
                t1 += p.TangentImpulse1;
                t2 += p.TangentImpulse2;
            }
            WideVector3.Lane(ref w.Tangent1, lane) = t1;
            WideVector3.Lane(ref w.Tangent2, lane) = t2;
            LoadPoint(ref w.AnchorA0, ref w.AnchorB0, ref w.Separation0, ref w.Impulse0, lane, m.Point0);
            LoadPoint(ref w.AnchorA1, ref w.AnchorB1, ref w.Separation1, ref w.Impulse1, lane, m.Point1);
            LoadPoint(ref w.AnchorA2, ref w.AnchorB2, ref w.Separation2, ref w.Impulse2, lane, m.Point2);
            LoadPoint(ref w.AnchorA3, ref w.AnchorB3, ref w.Separation3, ref w.Impulse3, lane, m.Point3);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void LoadPoint(ref WideVector3 anchorA, ref WideVector3 anchorB, ref Vector<float> separation, ref Vector<float> impulse, int lane, in ContactPoint p)
        {
            anchorA.Set(lane, p.AnchorA);
            anchorB.Set(lane, p.AnchorB);
            WideVector3.Lane(ref separation, lane) = p.Separation;
            WideVector3.Lane(ref impulse, lane) = p.NormalImpulse;
        }

        /// <summary>One normal row of a point before the block pairs are chosen.</summary>
        struct PreparedRow
        {
            public WideVector3 AngularA, AngularB, VelocityA, VelocityB;
            public Vector<float> K, Separation, Impulse, Approach;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<float> Inverse(Vector<float> k) =>
            Vector.ConditionalSelect(Vector.GreaterThan(k, new Vector<float>(1e-30f)), Vector<float>.One / k, Vector<float>.Zero);

        // ContactRow.Setup and ContactRow.Velocity, lane-wise.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static PreparedRow Row(in WideVector3 rA, in WideVector3 rB, in WideVector3 n, Vector<float> mass, in BodyLanes l)
        {
            PreparedRow r;
            r.AngularA = WideVector3.Cross(rA, n);
            r.AngularB = WideVector3.Cross(rB, n);
            r.VelocityA = l.IA.Transform(r.AngularA);
            r.VelocityB = l.IB.Transform(r.AngularB);
            r.K = mass + WideVector3.Dot(r.AngularA, r.VelocityA) + WideVector3.Dot(r.AngularB, r.VelocityB);
            r.Approach = RowVelocity(r.AngularA, r.AngularB, n, l);
            r.Separation = default;
            r.Impulse = default;
            return r;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static PreparedRow Select(Vector<int> mask, in PreparedRow a, in PreparedRow b) => new PreparedRow
        {
            AngularA = Select(mask, a.AngularA, b.AngularA),
            AngularB = Select(mask, a.AngularB, b.AngularB),
            VelocityA = Select(mask, a.VelocityA, b.VelocityA),
            VelocityB = Select(mask, a.VelocityB, b.VelocityB),
            K = Vector.ConditionalSelect(mask, a.K, b.K),
            Separation = Vector.ConditionalSelect(mask, a.Separation, b.Separation),
            Impulse = Vector.ConditionalSelect(mask, a.Impulse, b.Impulse),
            Approach = Vector.ConditionalSelect(mask, a.Approach, b.Approach),
        };

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static WideVector3 Select(Vector<int> mask, in WideVector3 a, in WideVector3 b) => new WideVector3
        {
            X = Vector.ConditionalSelect(mask, a.X, b.X),
            Y = Vector.ConditionalSelect(mask, a.Y, b.Y),
            Z = Vector.ConditionalSelect(mask, a.Z, b.Z),
        };

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<float> DistanceSquared(in PreparedRow a, in PreparedRow b)
        {
            WideVector3 da = a.AngularA, db = a.AngularB;
            da.Subtract(b.AngularA);
            db.Subtract(b.AngularB);
            return WideVector3.Dot(da, da) + WideVector3.Dot(db, db);
        }

        // Returns the lanes (bits) whose block pairs are ill-conditioned; far: the point paired with point 0.
        static int PrepareGroup(ref WideContact w, ref WideImpact impact, in ManifoldLanes m, in BodyLanes l, Vector<float> warm, out Vector<int> far)
        {
            WideVector3 n = m.Normal;
            Vector<float> mass = l.InvMassA + l.InvMassB;
            PreparedRow p0 = Row(m.AnchorA0, m.AnchorB0, n, mass, l);
            PreparedRow p1 = Row(m.AnchorA1, m.AnchorB1, n, mass, l);
            PreparedRow p2 = Row(m.AnchorA2, m.AnchorB2, n, mass, l);
            PreparedRow p3 = Row(m.AnchorA3, m.AnchorB3, n, mass, l);
            p0.Separation = m.Separation0;
            p1.Separation = m.Separation1;
            p2.Separation = m.Separation2;
            p3.Separation = m.Separation3;
            p0.Impulse = warm * m.Impulse0;
            p1.Impulse = warm * m.Impulse1;
            p2.Impulse = warm * m.Impulse2;
            p3.Impulse = warm * m.Impulse3;

            // ContactBlockSolver.Prepare: the point farthest from point 0 (first of equals) pairs
            // with it, the other two pair up in point order.
            Vector<float> best = DistanceSquared(p1, p0);
            Vector<float> d2 = DistanceSquared(p2, p0), d3 = DistanceSquared(p3, p0);
            Vector<int> is2 = Vector.GreaterThan(d2, best);
            best = Vector.Max(best, d2);
            Vector<int> is3 = Vector.GreaterThan(d3, best);
            is2 = Vector.AndNot(is2, is3);
            Vector<int> is1 = Vector.AndNot(Vector.AndNot(new Vector<int>(-1), is2), is3);
            far = Vector.ConditionalSelect(is3, new Vector<int>(3), Vector.ConditionalSelect(is2, new Vector<int>(2), Vector<int>.One));
            PreparedRow s1 = Select(is1, p1, Select(is2, p2, p3));
            PreparedRow s2 = Select(is1, p2, p1);
            PreparedRow s3 = Select(is3, p2, p3);

            int reject = Pair(ref w.K11a, ref w.K12a, ref w.K22a, p0, s1, mass) | Pair(ref w.K11b, ref w.K12b, ref w.K22b, s2, s3, mass);
            StoreRow(ref w.P0, ref impact.P0, p0);
            StoreRow(ref w.P1, ref impact.P1, s1);
            StoreRow(ref w.P2, ref impact.P2, s2);
            StoreRow(ref w.P3, ref impact.P3, s3);
            w.Loaded = Vector<int>.Zero;
            impact.Restitution = m.Restitution;

            // Patch friction at the centroid (the scalar prepare's sums, in point order).
            var quarter = new Vector<float>(0.25f);
            WideVector3 cA = m.AnchorA0, cB = m.AnchorB0;
            cA.Add(m.AnchorA1);
            cA.Add(m.AnchorA2);
            cA.Add(m.AnchorA3);
            cB.Add(m.AnchorB1);
            cB.Add(m.AnchorB2);
            cB.Add(m.AnchorB3);
            cA = WideVector3.Scale(cA, quarter);
            cB = WideVector3.Scale(cB, quarter);
            Tangents(n, out WideVector3 t1, out WideVector3 t2);
            w.Normal = n;
            w.Friction = m.Friction;
            w.CentroidA = cA;
            w.CentroidB = cB;
            w.FrictionMass1 = FrictionMass(cA, cB, t1, mass, l);
            w.FrictionMass2 = FrictionMass(cA, cB, t2, mass, l);
            w.FrictionImpulse1 = warm * m.Tangent1;
            w.FrictionImpulse2 = warm * m.Tangent2;

            // Twist friction: the arm is the points' mean distance from the centroid.
            Vector<float> radius = Arm(m.AnchorA0, cA, n) + Arm(m.AnchorA1, cA, n) + Arm(m.AnchorA2, cA, n) + Arm(m.AnchorA3, cA, n);
            radius *= quarter;
            var arm = Vector.GreaterThan(radius, Vector<float>.Zero);
            w.TwistRadius = radius;
            w.TwistMass = Vector.ConditionalSelect(arm,
                Inverse(WideVector3.Dot(n, l.IA.Transform(n)) + WideVector3.Dot(n, l.IB.Transform(n))), Vector<float>.Zero);
            w.TwistImpulse = Vector.ConditionalSelect(arm, warm * m.Twist, Vector<float>.Zero);
            return reject;
        }

        // ContactRow.Setup's effective mass of a friction row at the centroid.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<float> FrictionMass(in WideVector3 cA, in WideVector3 cB, in WideVector3 t, Vector<float> mass, in BodyLanes l)
        {
            WideVector3 angularA = WideVector3.Cross(cA, t), angularB = WideVector3.Cross(cB, t);
            return Inverse(mass + WideVector3.Dot(angularA, l.IA.Transform(angularA)) + WideVector3.Dot(angularB, l.IB.Transform(angularB)));
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static Vector<float> Arm(in WideVector3 anchor, in WideVector3 centroid, in WideVector3 n)
        {
            WideVector3 d = anchor;
            d.Subtract(centroid);
            d.SubtractScaled(n, WideVector3.Dot(d, n));
            return Vector.SquareRoot(WideVector3.Dot(d, d));
        }

        // ContactBlockSolver.MakePair: K of the pair, and the lanes (bits) where it is ill-conditioned.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static int Pair(ref Vector<float> k11, ref Vector<float> k12, ref Vector<float> k22, in PreparedRow a, in PreparedRow b, Vector<float> mass)
        {
            k11 = a.K;
            k22 = b.K;
            k12 = mass + WideVector3.Dot(a.AngularA, b.VelocityA) + WideVector3.Dot(a.AngularB, b.VelocityB);
            Vector<float> det = k11 * k22 - k12 * k12;
            Vector<int> good = Vector.BitwiseAnd(
                Vector.BitwiseAnd(Vector.GreaterThan(k11, Vector<float>.Zero), Vector.GreaterThan(k22, Vector<float>.Zero)),
                Vector.LessThan(k11 * k11, new Vector<float>(1000f) * det));
            int bad = 0;
            for (int lane = 0; lane < Vector<int>.Count; lane++)
                if (good.GetElement(lane) == 0) bad |= 1 << lane;
            return bad;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static void StoreRow(ref WidePoint p, ref WideImpactPoint i, in PreparedRow r)
        {
            p.AngularA = r.AngularA;
            p.AngularB = r.AngularB;
            p.Separation = r.Separation;
            p.Impulse = r.Impulse;
            i.EffectiveMass = Inverse(r.K);
            i.RelativeVelocity = r.Approach;
            i.Applied = Vector<float>.Zero;
            i.LastSubstep = Vector<float>.Zero;
        }

        static void ClearLane(ref WideContact w, ref WideImpact impact, int lane)
        {
            // Every field is a whole number of Vector<float>: clear the lane's float in each.
            int fields = Unsafe.SizeOf<WideContact>() / Unsafe.SizeOf<Vector<float>>();
            ref Vector<float> f = ref Unsafe.As<WideContact, Vector<float>>(ref w);
            for (int k = 0; k < fields; k++) WideVector3.Lane(ref Unsafe.Add(ref f, k), lane) = 0;
            int impactFields = Unsafe.SizeOf<WideImpact>() / Unsafe.SizeOf<Vector<float>>();
            ref Vector<float> i = ref Unsafe.As<WideImpact, Vector<float>>(ref impact);
            for (int k = 0; k < impactFields; k++) WideVector3.Lane(ref Unsafe.Add(ref i, k), lane) = 0;
        }
    }
}
#endif
