using System;
using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The velocity-level contact solver shared by <see cref="PgsSolver"/> and
    /// <see cref="TgsSolver"/>: building the rows of a manifold, warm starting, one
    /// Gauss-Seidel pass (normal rows, then friction bounded by the normal impulse just
    /// computed, then rolling resistance), restitution and the write-back of impulses.
    /// <para>
    /// Friction acts on the manifold as a whole (patch friction, as in PhysX and Bepu): two
    /// tangent rows at the centroid of the points, their impulse kept inside the circle
    /// mu * (sum of the normal impulses), and a twist row about the normal bounded by
    /// mu * (sum of normal impulses) * (mean distance of the points from the centroid). A face
    /// contact is statically indeterminate (four normal rows, three degrees of freedom), so
    /// its normal impulses may settle unevenly; per-point friction would then turn a sliding
    /// box about the normal, while patch friction does not depend on how the load is shared.
    /// </para>
    /// <para>
    /// The separation of each point is carried through the step from the bodies' motion:
    /// s = s0 + n.(dpB - dpA) + dthetaB.(rB x n) - dthetaA.(rA x n), the first-order change of the
    /// gap for displacements dp and small rotations dtheta, so substeps see contacts close or
    /// open without a new narrow phase. A positive s is a speculative contact: the row lets
    /// the bodies approach by s in this (sub)step and no further.
    /// </para>
    /// </summary>
    internal static class ContactSolver
    {
        /// <summary>
        /// Builds the constraint of manifold <paramref name="m"/> between solver bodies
        /// <paramref name="ia"/> and <paramref name="ib"/>; its points go to
        /// <paramref name="points"/> from <paramref name="firstPoint"/> on. Impulses from the
        /// manifold are scaled by the step's <see cref="ContactStep.WarmScale"/> (0 turns warm starting off).
        /// </summary>
        public static void Prepare(ref ContactConstraint c, ContactConstraintPoint[] points, int firstPoint,
            ref ContactManifold m, int manifoldIndex, SolverBody[] bodies, int ia, int ib, in ContactStep step)
        {
            float warmScale = step.WarmScale;
            ref SolverBody a = ref bodies[ia];
            ref SolverBody b = ref bodies[ib];
            c.BodyA = ia;
            c.BodyB = ib;
            c.FirstPoint = firstPoint;
            c.PointCount = m.PointCount;
            c.Manifold = manifoldIndex;
            c.InvMassA = a.LinearInverseMass;
            c.InvMassB = b.LinearInverseMass;
            Vector3 n = m.Normal;
            c.Normal = n;
            TangentBasis.Build(n, out c.Tangent1, out c.Tangent2);
            c.Friction = m.Friction;
            c.Restitution = m.Restitution;
            // A body that cannot move makes the contact stiffer: the other side's mass is all
            // the spring sees (Box2D v3 doubles the contact hertz for static contacts).
            c.Softness = a.IsDynamic == 0 || b.IsDynamic == 0 ? step.FixedBody : step.Contact;

            Vector3 vA = a.LinearVelocity, wA = a.AngularVelocity, vB = b.LinearVelocity, wB = b.AngularVelocity;
            Vector3 centroidA = Vector3.Zero, centroidB = Vector3.Zero;
            float friction1 = 0, friction2 = 0;
            for (int i = 0; i < m.PointCount; i++)
            {
                ref ContactPoint mp = ref ContactManifold.Point(ref m, i);
                ref ContactConstraintPoint p = ref points[firstPoint + i];
                p.Normal.Setup(mp.AnchorA, mp.AnchorB, n, a.InverseMassAlong(n), a.InverseInertia, b.InverseMassAlong(n), b.InverseInertia);
                p.Normal.Impulse = warmScale * mp.NormalImpulse;
                friction1 += mp.TangentImpulse1;
                friction2 += mp.TangentImpulse2;
                centroidA += mp.AnchorA;
                centroidB += mp.AnchorB;
                p.Separation = mp.Separation;
                p.RelativeVelocity = p.Normal.Velocity(n, vA, wA, vB, wB);
                mp.RelativeNormalVelocity = p.RelativeVelocity;
                p.MaxNormalImpulse = 0;
                p.Applied = 0;
                p.LastSubstep = 0;
                p.ManifoldPoint = i;
            }

            // Patch friction at the centroid; the twist arm is the points' mean distance from it.
            float inv = 1f / m.PointCount;
            centroidA *= inv;
            centroidB *= inv;
            c.Friction1.Setup(centroidA, centroidB, c.Tangent1, a.InverseMassAlong(c.Tangent1), a.InverseInertia, b.InverseMassAlong(c.Tangent1), b.InverseInertia);
            c.Friction2.Setup(centroidA, centroidB, c.Tangent2, a.InverseMassAlong(c.Tangent2), a.InverseInertia, b.InverseMassAlong(c.Tangent2), b.InverseInertia);
            c.Friction1.Impulse = warmScale * friction1;
            c.Friction2.Impulse = warmScale * friction2;
            float radius = 0;
            for (int i = 0; i < m.PointCount; i++)
            {
                Vector3 d = ContactManifold.Point(ref m, i).AnchorA - centroidA;
                radius += (d - Vector3.Dot(d, n) * n).Length();
            }
            c.TwistRadius = radius * inv;
            c.TwistMass = c.TwistRadius > 0 ? AngularMass(n, a.InverseInertia, b.InverseInertia) : 0;
            // The manifold's rolling impulse carries the twist impulse in its normal component.
            c.TwistImpulse = c.TwistRadius > 0 ? warmScale * Vector3.Dot(m.RollingImpulse, n) : 0;

            c.RollingFriction = m.RollingFriction;
            c.RollingImpulse1 = c.RollingImpulse2 = 0;
            c.RollingMass1 = c.RollingMass2 = 0;
            if (m.RollingFriction > 0)
            {
                c.RollingMass1 = AngularMass(c.Tangent1, a.InverseInertia, b.InverseInertia);
                c.RollingMass2 = AngularMass(c.Tangent2, a.InverseInertia, b.InverseInertia);
                c.RollingImpulse1 = warmScale * Vector3.Dot(m.RollingImpulse, c.Tangent1);
                c.RollingImpulse2 = warmScale * Vector3.Dot(m.RollingImpulse, c.Tangent2);
            }

            if (step.Block) ContactBlockSolver.Prepare(ref c, points);
            else
            {
                c.Block0 = ContactBlockPair.None;
                c.Block1 = ContactBlockPair.None;
            }
        }

        static float AngularMass(Vector3 axis, in Fulcrum.Mathematics.Mat3 iA, in Fulcrum.Mathematics.Mat3 iB)
        {
            float k = Vector3.Dot(axis, iA * axis) + Vector3.Dot(axis, iB * axis);
            return k > 1e-30f ? 1f / k : 0f;
        }

        /// <summary>Applies the accumulated impulses (the warm start) to the bodies.</summary>
        public static void WarmStart(ref ContactConstraint c, ContactConstraintPoint[] points, SolverBody[] bodies)
        {
            ref SolverBody a = ref bodies[c.BodyA];
            ref SolverBody b = ref bodies[c.BodyB];
            float l1 = c.Friction1.Impulse, l2 = c.Friction2.Impulse, normalSum = 0;
            Vector3 angularA = l1 * c.Friction1.VelocityA + l2 * c.Friction2.VelocityA;
            Vector3 angularB = l1 * c.Friction1.VelocityB + l2 * c.Friction2.VelocityB;
            for (int k = c.FirstPoint, end = c.FirstPoint + c.PointCount; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                float ln = p.Normal.Impulse;
                normalSum += ln;
                angularA += ln * p.Normal.VelocityA;
                angularB += ln * p.Normal.VelocityB;
            }
            Vector3 linear = normalSum * c.Normal + l1 * c.Tangent1 + l2 * c.Tangent2;
            Vector3 spin = c.TwistImpulse * c.Normal + c.RollingImpulse1 * c.Tangent1 + c.RollingImpulse2 * c.Tangent2;
            if (spin != Vector3.Zero)
            {
                angularA += a.InverseInertia * spin;
                angularB += b.InverseInertia * spin;
            }
            if (a.IsDynamic != 0)
            {
                a.LinearVelocity -= c.InvMassA * linear;
                a.AngularVelocity -= angularA;
            }
            if (b.IsDynamic != 0)
            {
                b.LinearVelocity += c.InvMassB * linear;
                b.AngularVelocity += angularB;
            }
        }

        /// <summary>
        /// One Gauss-Seidel pass over the manifold. With <paramref name="useBias"/> the normal
        /// rows are soft and push overlapping bodies apart (at most <see cref="ContactStep.MaxPushSpeed"/>);
        /// without it they are rigid and only remove approaching velocity (the relax pass, and
        /// every PGS velocity iteration). Speculative points (s &gt; 0) always allow an approach of
        /// s / h. Friction is bounded by mu times the normal impulse of this very pass, so it can
        /// never hold more than the contact presses (no creep on slopes).
        /// </summary>
        public static void Solve(ref ContactConstraint c, ContactConstraintPoint[] points, SolverBody[] bodies,
            in ContactStep step, bool useBias)
        {
            ref SolverBody a = ref bodies[c.BodyA];
            ref SolverBody b = ref bodies[c.BodyB];
            var v = new BodyPairVelocity { LinearA = a.LinearVelocity, AngularA = a.AngularVelocity, LinearB = b.LinearVelocity, AngularB = b.AngularVelocity };
            Vector3 mA = c.InvMassA, mB = c.InvMassB;
            Vector3 n = c.Normal;
            var motion = new ContactPairMotion(n, mA, mB, Vector3.Dot(n, b.DeltaPosition - a.DeltaPosition), a.DeltaAngle, b.DeltaAngle, c.Softness);
            int first = c.FirstPoint, end = first + c.PointCount;

            if (c.Block0.IsUsed)
            {
                SolveBlock(in c.Block0, points, motion, step, useBias, ref v);
                if (c.Block1.IsUsed)
                    SolveBlock(in c.Block1, points, motion, step, useBias, ref v);
                else if (c.PointCount == 3)
                {
                    // The point left out of the pair is solved on its own.
                    for (int k = first; k < end; k++)
                        if (k != c.Block0.I && k != c.Block0.J)
                            SolveNormal(ref points[k], motion, step, useBias, ref v);
                }
            }
            else
            {
                for (int k = first; k < end; k++)
                    SolveNormal(ref points[k], motion, step, useBias, ref v);
            }
            Vector3 vA = v.LinearA, wA = v.AngularA, vB = v.LinearB, wB = v.AngularB;

            float mu = c.Friction;
            float totalNormal = 0;
            for (int k = first; k < end; k++) totalNormal += points[k].Normal.Impulse;
            Vector3 t1 = c.Tangent1, t2 = c.Tangent2;
            {
                float maxFriction = mu * totalNormal;
                float old1 = c.Friction1.Impulse, old2 = c.Friction2.Impulse;
                float new1 = old1 - c.Friction1.EffectiveMass * c.Friction1.Velocity(t1, vA, wA, vB, wB);
                float new2 = old2 - c.Friction2.EffectiveMass * c.Friction2.Velocity(t2, vA, wA, vB, wB);
                // Coulomb's cone is round: clamp the friction impulse's length, not each axis,
                // so a body sliding diagonally feels the same friction as one sliding along t1.
                float len2 = new1 * new1 + new2 * new2;
                if (len2 > maxFriction * maxFriction)
                {
                    float scale = maxFriction / MathF.Sqrt(len2);
                    new1 *= scale;
                    new2 *= scale;
                }
                c.Friction1.Impulse = new1;
                c.Friction2.Impulse = new2;
                float d1 = new1 - old1, d2 = new2 - old2;
                Vector3 impulse = d1 * t1 + d2 * t2;
                vA -= mA * impulse;
                wA -= d1 * c.Friction1.VelocityA + d2 * c.Friction2.VelocityA;
                vB += mB * impulse;
                wB += d1 * c.Friction1.VelocityB + d2 * c.Friction2.VelocityB;
            }
            if (c.TwistMass > 0)
            {
                // Twist friction: spinning about the normal is resisted by the friction of the
                // patch at its mean radius.
                float maxTwist = mu * totalNormal * c.TwistRadius;
                float old = c.TwistImpulse;
                float total = Math.Clamp(old - c.TwistMass * Vector3.Dot(n, wB - wA), -maxTwist, maxTwist);
                c.TwistImpulse = total;
                Vector3 l = (total - old) * n;
                wA -= a.InverseInertia * l;
                wB += b.InverseInertia * l;
            }

            if (c.RollingFriction > 0)
            {
                // Rolling resistance: the relative rolling speed about the tangents is driven to
                // zero by a torque of at most (rolling coefficient) x (normal force).
                float maxRolling = c.RollingFriction * totalNormal;
                Vector3 wRel = wB - wA;
                float old1 = c.RollingImpulse1, old2 = c.RollingImpulse2;
                float new1 = old1 - c.RollingMass1 * Vector3.Dot(t1, wRel);
                float new2 = old2 - c.RollingMass2 * Vector3.Dot(t2, wRel);
                float len2 = new1 * new1 + new2 * new2;
                if (len2 > maxRolling * maxRolling)
                {
                    float s = maxRolling / MathF.Sqrt(len2);
                    new1 *= s;
                    new2 *= s;
                }
                c.RollingImpulse1 = new1;
                c.RollingImpulse2 = new2;
                Vector3 l = (new1 - old1) * t1 + (new2 - old2) * t2;
                wA -= a.InverseInertia * l;
                wB += b.InverseInertia * l;
            }

            a.StoreVelocities(vA, wA);
            b.StoreVelocities(vB, wB);
        }

        static float CurrentSeparation(in ContactConstraintPoint p, in ContactPairMotion m) =>
            p.Separation + m.Drift + Vector3.Dot(m.DThetaB, p.Normal.AngularB) - Vector3.Dot(m.DThetaA, p.Normal.AngularA);

        static void RowTerms(float s, in Softness soft, in ContactStep step, bool useBias, out float bias, out float massScale, out float impulseScale)
        {
            if (s > 0)
            {
                bias = s * step.InverseH;
                massScale = 1;
                impulseScale = 0;
            }
            else if (useBias)
            {
                bias = MathF.Max(soft.BiasRate * s, -step.MaxPushSpeed);
                massScale = soft.MassScale;
                impulseScale = soft.ImpulseScale;
            }
            else
            {
                bias = 0;
                massScale = 1;
                impulseScale = 0;
            }
        }

        static void SolveNormal(ref ContactConstraintPoint p, in ContactPairMotion m, in ContactStep step, bool useBias, ref BodyPairVelocity v)
        {
            float s = CurrentSeparation(p, m);
            RowTerms(s, m.Softness, step, useBias, out float bias, out float massScale, out float impulseScale);
            Vector3 n = m.Normal;
            float vn = p.Normal.Velocity(n, v.LinearA, v.AngularA, v.LinearB, v.AngularB);
            float old = p.Normal.Impulse;
            float impulse = -p.Normal.EffectiveMass * massScale * (vn + bias) - impulseScale * old;
            float total = MathF.Max(old + impulse, 0f);
            impulse = total - old;
            p.Normal.Impulse = total;
            if (total > p.MaxNormalImpulse)
            {
                RecordImpact(ref p, vn);
                p.MaxNormalImpulse = total;
            }
            Vector3 P = impulse * n;
            v.LinearA -= m.InvMassA * P;
            v.AngularA -= impulse * p.Normal.VelocityA;
            v.LinearB += m.InvMassB * P;
            v.AngularB += impulse * p.Normal.VelocityB;
        }

        static void SolveBlock(in ContactBlockPair pair, ContactConstraintPoint[] points, in ContactPairMotion m, in ContactStep step, bool useBias,
            ref BodyPairVelocity v)
        {
            float s1 = CurrentSeparation(points[pair.I], m);
            float s2 = CurrentSeparation(points[pair.J], m);
            RowTerms(s1, m.Softness, step, useBias, out float bias1, out float ms1, out float is1);
            RowTerms(s2, m.Softness, step, useBias, out float bias2, out float ms2, out float is2);
            // gamma = K impulseScale / massScale: the compliance the soft row adds to the diagonal.
            float gamma1 = is1 > 0 ? pair.K11 * is1 / ms1 : 0;
            float gamma2 = is2 > 0 ? pair.K22 * is2 / ms2 : 0;
            ContactBlockSolver.SolvePair(pair, points, m, bias1, gamma1, bias2, gamma2, ref v);
        }

        /// <summary>
        /// The approach speed restitution answers: the relative normal velocity just before the
        /// point first carried an impulse in this step, but no faster than the free approach
        /// left in RelativeVelocity: the velocity after gravity and applied forces, before any
        /// contact pushed (PGS: from Prepare, after its velocity update; TGS: from
        /// <see cref="RefreshApproach"/> at the start of every substep). A body that reaches the
        /// surface in the middle of a step (a speculative contact closing) has gained speed
        /// since the step began; its speed in the substep where it lands is the impact speed to
        /// a substep's gravity. The bound matters where other contacts of the same (sub)step
        /// drove the bodies together: in a Newton's cradle with small gaps, ball 2 is pushed
        /// into ball 3 by the inelastic solve of 1-2; answering that push as well as 1-2's
        /// approach asks both pairs to separate at once, which adds energy (2.3x under TGS,
        /// 5.8x under PGS with 1 cm gaps). Such a push is not an impact: it is left to the
        /// next (sub)step, where it is one. A point warm started under load records its
        /// (resting) velocity at once.
        /// </summary>
        internal static void RecordImpact(ref ContactConstraintPoint p, float vn)
        {
            if (p.MaxNormalImpulse == 0) p.RelativeVelocity = MathF.Max(vn, p.RelativeVelocity);
        }

        /// <summary>
        /// Sets the free approach speed (see <see cref="RecordImpact"/>) of the points that have
        /// carried no impulse yet in this step to their relative normal velocity now: TGS calls
        /// it after each substep's velocity update, before the warm start.
        /// </summary>
        public static void RefreshApproach(ref ContactConstraint c, ContactConstraintPoint[] points, SolverBody[] bodies)
        {
            if (c.Restitution == 0) return;
            ref SolverBody a = ref bodies[c.BodyA];
            ref SolverBody b = ref bodies[c.BodyB];
            for (int k = c.FirstPoint, end = c.FirstPoint + c.PointCount; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                if (p.MaxNormalImpulse == 0)
                    p.RelativeVelocity = p.Normal.Velocity(c.Normal, a.LinearVelocity, a.AngularVelocity, b.LinearVelocity, b.AngularVelocity);
            }
        }

        /// <summary>
        /// Restitution after the solve (Box2D v3): points that approached faster than
        /// <paramref name="threshold"/> and carried an impulse get the separating velocity
        /// -e v0, v0 the approach speed of <see cref="RecordImpact"/>; slower contacts (resting
        /// ones) are left alone, so resting bodies never bounce. TGS runs it at the end of
        /// every substep, for the points whose impact is in that substep (none of their
        /// impulse applied by an earlier substep): an impact is answered once, in the substep
        /// it happens, so impacts that follow one another within a step (a Newton's cradle with
        /// small gaps) are resolved one after the other, as they happen.
        /// </summary>
        public static void ApplyRestitution(ref ContactConstraint c, ContactConstraintPoint[] points, SolverBody[] bodies, float threshold)
        {
            if (c.Restitution == 0) return;
            ref SolverBody a = ref bodies[c.BodyA];
            ref SolverBody b = ref bodies[c.BodyB];
            Vector3 vA = a.LinearVelocity, wA = a.AngularVelocity, vB = b.LinearVelocity, wB = b.AngularVelocity;
            Vector3 mA = c.InvMassA, mB = c.InvMassB;
            Vector3 n = c.Normal;
            float e = c.Restitution;
            for (int k = c.FirstPoint, end = c.FirstPoint + c.PointCount; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                if (p.RelativeVelocity > -threshold || p.MaxNormalImpulse == 0 || p.Applied != 0) continue;
                float vn = p.Normal.Velocity(n, vA, wA, vB, wB);
                float old = p.Normal.Impulse;
                float total = MathF.Max(old - p.Normal.EffectiveMass * (vn + e * p.RelativeVelocity), 0f);
                float impulse = total - old;
                p.Normal.Impulse = total;
                if (total > p.MaxNormalImpulse) p.MaxNormalImpulse = total;
                Vector3 P = impulse * n;
                vA -= mA * P;
                wA -= impulse * p.Normal.VelocityA;
                vB += mB * P;
                wB += impulse * p.Normal.VelocityB;
            }
            a.StoreVelocities(vA, wA);
            b.StoreVelocities(vB, wB);
        }

        /// <summary>
        /// Writes the accumulated impulses back into the manifold for the next step's warm
        /// start, scaled by <paramref name="scale"/> (substeps per step: the manifold holds
        /// impulses per step). <see cref="ContactManifold.RollingImpulse"/> carries the twist
        /// friction impulse along the normal and the rolling impulses along the tangents.
        /// </summary>
        public static void Store(in ContactConstraint c, ContactConstraintPoint[] points, ref ContactManifold m, float scale)
        {
            // The patch friction impulse is shared out evenly over the points (the contract keeps
            // friction per point); the next step sums it back.
            float share = scale / c.PointCount;
            for (int k = c.FirstPoint, end = c.FirstPoint + c.PointCount; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                ref ContactPoint mp = ref ContactManifold.Point(ref m, p.ManifoldPoint);
                mp.NormalImpulse = scale * p.Normal.Impulse;
                mp.AppliedImpulse = p.Applied + p.Normal.Impulse - p.LastSubstep;
                mp.TangentImpulse1 = share * c.Friction1.Impulse;
                mp.TangentImpulse2 = share * c.Friction2.Impulse;
                mp.RelativeNormalVelocity = p.RelativeVelocity;
            }
            m.RollingImpulse = scale * (c.TwistImpulse * c.Normal + c.RollingImpulse1 * c.Tangent1 + c.RollingImpulse2 * c.Tangent2);
        }
    }
}
