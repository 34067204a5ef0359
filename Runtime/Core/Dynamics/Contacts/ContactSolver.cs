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
        /// manifold are scaled by <paramref name="warmScale"/> (0 turns warm starting off).
        /// </summary>
        public static void Prepare(ref ContactConstraint c, ContactConstraintPoint[] points, int firstPoint,
            ref ContactManifold m, int manifoldIndex, SolverBody[] bodies, int ia, int ib,
            in Softness contactSoftness, in Softness fixedSoftness, float warmScale, bool block)
        {
            ref SolverBody a = ref bodies[ia];
            ref SolverBody b = ref bodies[ib];
            c.BodyA = ia;
            c.BodyB = ib;
            c.FirstPoint = firstPoint;
            c.PointCount = m.PointCount;
            c.Manifold = manifoldIndex;
            c.InvMassA = a.InverseMass;
            c.InvMassB = b.InverseMass;
            Vector3 n = m.Normal;
            c.Normal = n;
            TangentBasis.Build(n, out c.Tangent1, out c.Tangent2);
            c.Friction = m.Friction;
            c.Restitution = m.Restitution;
            // A body that cannot move makes the contact stiffer: the other side's mass is all
            // the spring sees (Box2D v3 doubles the contact hertz for static contacts).
            c.Softness = a.IsDynamic == 0 || b.IsDynamic == 0 ? fixedSoftness : contactSoftness;

            Vector3 vA = a.LinearVelocity, wA = a.AngularVelocity, vB = b.LinearVelocity, wB = b.AngularVelocity;
            for (int i = 0; i < m.PointCount; i++)
            {
                ref ContactPoint mp = ref ContactManifold.Point(ref m, i);
                ref ContactConstraintPoint p = ref points[firstPoint + i];
                p.Normal.Setup(mp.AnchorA, mp.AnchorB, n, a.InverseMass, a.InverseInertia, b.InverseMass, b.InverseInertia);
                p.Tangent1.Setup(mp.AnchorA, mp.AnchorB, c.Tangent1, a.InverseMass, a.InverseInertia, b.InverseMass, b.InverseInertia);
                p.Tangent2.Setup(mp.AnchorA, mp.AnchorB, c.Tangent2, a.InverseMass, a.InverseInertia, b.InverseMass, b.InverseInertia);
                p.Normal.Impulse = warmScale * mp.NormalImpulse;
                p.Tangent1.Impulse = warmScale * mp.TangentImpulse1;
                p.Tangent2.Impulse = warmScale * mp.TangentImpulse2;
                p.Separation = mp.Separation;
                p.RelativeVelocity = p.Normal.Velocity(n, vA, wA, vB, wB);
                mp.RelativeNormalVelocity = p.RelativeVelocity;
                p.MaxNormalImpulse = 0;
                p.ManifoldPoint = i;
            }

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

            if (block) ContactBlockSolver.Prepare(ref c, points);
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
            Vector3 linear = Vector3.Zero, angularA = Vector3.Zero, angularB = Vector3.Zero;
            for (int k = c.FirstPoint, end = c.FirstPoint + c.PointCount; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                float ln = p.Normal.Impulse, l1 = p.Tangent1.Impulse, l2 = p.Tangent2.Impulse;
                linear += ln * c.Normal + l1 * c.Tangent1 + l2 * c.Tangent2;
                angularA += ln * p.Normal.VelocityA + l1 * p.Tangent1.VelocityA + l2 * p.Tangent2.VelocityA;
                angularB += ln * p.Normal.VelocityB + l1 * p.Tangent1.VelocityB + l2 * p.Tangent2.VelocityB;
            }
            if (c.RollingFriction > 0)
            {
                Vector3 r = c.RollingImpulse1 * c.Tangent1 + c.RollingImpulse2 * c.Tangent2;
                angularA += a.InverseInertia * r;
                angularB += b.InverseInertia * r;
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
        /// rows are soft and push overlapping bodies apart (at most <paramref name="maxPushSpeed"/>);
        /// without it they are rigid and only remove approaching velocity (the relax pass, and
        /// every PGS velocity iteration). Speculative points (s &gt; 0) always allow an approach of
        /// s / h. Friction is bounded by mu times the normal impulse of this very pass, so it can
        /// never hold more than the contact presses (no creep on slopes).
        /// </summary>
        public static void Solve(ref ContactConstraint c, ContactConstraintPoint[] points, SolverBody[] bodies,
            float invH, float maxPushSpeed, bool useBias)
        {
            ref SolverBody a = ref bodies[c.BodyA];
            ref SolverBody b = ref bodies[c.BodyB];
            Vector3 vA = a.LinearVelocity, wA = a.AngularVelocity, vB = b.LinearVelocity, wB = b.AngularVelocity;
            float mA = c.InvMassA, mB = c.InvMassB;
            Vector3 n = c.Normal;
            Vector3 dThetaA = a.DeltaAngle, dThetaB = b.DeltaAngle;
            float drift = Vector3.Dot(n, b.DeltaPosition - a.DeltaPosition);
            Softness soft = c.Softness;
            int first = c.FirstPoint, end = first + c.PointCount;

            if (c.Block0.IsUsed)
            {
                SolveBlock(in c.Block0, points, n, mA, mB, drift, dThetaA, dThetaB, soft, invH, maxPushSpeed, useBias, ref vA, ref wA, ref vB, ref wB);
                if (c.Block1.IsUsed)
                    SolveBlock(in c.Block1, points, n, mA, mB, drift, dThetaA, dThetaB, soft, invH, maxPushSpeed, useBias, ref vA, ref wA, ref vB, ref wB);
                else if (c.PointCount == 3)
                {
                    // The point left out of the pair is solved on its own.
                    for (int k = first; k < end; k++)
                        if (k != c.Block0.I && k != c.Block0.J)
                            SolveNormal(ref points[k], n, mA, mB, drift, dThetaA, dThetaB, soft, invH, maxPushSpeed, useBias, ref vA, ref wA, ref vB, ref wB);
                }
            }
            else
            {
                for (int k = first; k < end; k++)
                    SolveNormal(ref points[k], n, mA, mB, drift, dThetaA, dThetaB, soft, invH, maxPushSpeed, useBias, ref vA, ref wA, ref vB, ref wB);
            }

            float mu = c.Friction;
            float totalNormal = 0;
            Vector3 t1 = c.Tangent1, t2 = c.Tangent2;
            for (int k = first; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                totalNormal += p.Normal.Impulse;
                float maxFriction = mu * p.Normal.Impulse;
                float old1 = p.Tangent1.Impulse, old2 = p.Tangent2.Impulse;
                float new1 = old1 - p.Tangent1.EffectiveMass * p.Tangent1.Velocity(t1, vA, wA, vB, wB);
                float new2 = old2 - p.Tangent2.EffectiveMass * p.Tangent2.Velocity(t2, vA, wA, vB, wB);
                // Coulomb's cone is round: clamp the friction impulse's length, not each axis,
                // so a body sliding diagonally feels the same friction as one sliding along t1.
                float len2 = new1 * new1 + new2 * new2;
                if (len2 > maxFriction * maxFriction)
                {
                    float s = maxFriction / MathF.Sqrt(len2);
                    new1 *= s;
                    new2 *= s;
                }
                p.Tangent1.Impulse = new1;
                p.Tangent2.Impulse = new2;
                float d1 = new1 - old1, d2 = new2 - old2;
                Vector3 impulse = d1 * t1 + d2 * t2;
                vA -= mA * impulse;
                wA -= d1 * p.Tangent1.VelocityA + d2 * p.Tangent2.VelocityA;
                vB += mB * impulse;
                wB += d1 * p.Tangent1.VelocityB + d2 * p.Tangent2.VelocityB;
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

            if (a.IsDynamic != 0)
            {
                a.LinearVelocity = vA;
                a.AngularVelocity = wA;
            }
            if (b.IsDynamic != 0)
            {
                b.LinearVelocity = vB;
                b.AngularVelocity = wB;
            }
        }

        static float CurrentSeparation(in ContactConstraintPoint p, float drift, Vector3 dThetaA, Vector3 dThetaB) =>
            p.Separation + drift + Vector3.Dot(dThetaB, p.Normal.AngularB) - Vector3.Dot(dThetaA, p.Normal.AngularA);

        static void RowTerms(float s, in Softness soft, float invH, float maxPushSpeed, bool useBias, out float bias, out float massScale, out float impulseScale)
        {
            if (s > 0)
            {
                bias = s * invH;
                massScale = 1;
                impulseScale = 0;
            }
            else if (useBias)
            {
                bias = MathF.Max(soft.BiasRate * s, -maxPushSpeed);
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

        static void SolveNormal(ref ContactConstraintPoint p, Vector3 n, float mA, float mB, float drift, Vector3 dThetaA, Vector3 dThetaB,
            in Softness soft, float invH, float maxPushSpeed, bool useBias,
            ref Vector3 vA, ref Vector3 wA, ref Vector3 vB, ref Vector3 wB)
        {
            float s = CurrentSeparation(p, drift, dThetaA, dThetaB);
            RowTerms(s, soft, invH, maxPushSpeed, useBias, out float bias, out float massScale, out float impulseScale);
            float vn = p.Normal.Velocity(n, vA, wA, vB, wB);
            float old = p.Normal.Impulse;
            float impulse = -p.Normal.EffectiveMass * massScale * (vn + bias) - impulseScale * old;
            float total = MathF.Max(old + impulse, 0f);
            impulse = total - old;
            p.Normal.Impulse = total;
            if (total > p.MaxNormalImpulse) p.MaxNormalImpulse = total;
            Vector3 P = impulse * n;
            vA -= mA * P;
            wA -= impulse * p.Normal.VelocityA;
            vB += mB * P;
            wB += impulse * p.Normal.VelocityB;
        }

        static void SolveBlock(in ContactBlockPair pair, ContactConstraintPoint[] points, Vector3 n, float mA, float mB,
            float drift, Vector3 dThetaA, Vector3 dThetaB, in Softness soft, float invH, float maxPushSpeed, bool useBias,
            ref Vector3 vA, ref Vector3 wA, ref Vector3 vB, ref Vector3 wB)
        {
            float s1 = CurrentSeparation(points[pair.I], drift, dThetaA, dThetaB);
            float s2 = CurrentSeparation(points[pair.J], drift, dThetaA, dThetaB);
            RowTerms(s1, soft, invH, maxPushSpeed, useBias, out float bias1, out float ms1, out float is1);
            RowTerms(s2, soft, invH, maxPushSpeed, useBias, out float bias2, out float ms2, out float is2);
            // gamma = K impulseScale / massScale: the compliance the soft row adds to the diagonal.
            float gamma1 = is1 > 0 ? pair.K11 * is1 / ms1 : 0;
            float gamma2 = is2 > 0 ? pair.K22 * is2 / ms2 : 0;
            ContactBlockSolver.SolvePair(pair, points, n, mA, mB, bias1, gamma1, bias2, gamma2, ref vA, ref wA, ref vB, ref wB);
        }

        /// <summary>
        /// Restitution after the solve (Box2D v3): points that approached faster than
        /// <paramref name="threshold"/> before the solve and carried an impulse get the
        /// separating velocity -e v0, from the relative velocity before the solve; slower
        /// contacts (resting ones) are left alone, so resting bodies never bounce.
        /// </summary>
        public static void ApplyRestitution(ref ContactConstraint c, ContactConstraintPoint[] points, SolverBody[] bodies, float threshold)
        {
            if (c.Restitution == 0) return;
            ref SolverBody a = ref bodies[c.BodyA];
            ref SolverBody b = ref bodies[c.BodyB];
            Vector3 vA = a.LinearVelocity, wA = a.AngularVelocity, vB = b.LinearVelocity, wB = b.AngularVelocity;
            float mA = c.InvMassA, mB = c.InvMassB;
            Vector3 n = c.Normal;
            float e = c.Restitution;
            for (int k = c.FirstPoint, end = c.FirstPoint + c.PointCount; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                if (p.RelativeVelocity > -threshold || p.MaxNormalImpulse == 0) continue;
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
            if (a.IsDynamic != 0)
            {
                a.LinearVelocity = vA;
                a.AngularVelocity = wA;
            }
            if (b.IsDynamic != 0)
            {
                b.LinearVelocity = vB;
                b.AngularVelocity = wB;
            }
        }

        /// <summary>
        /// Writes the accumulated impulses back into the manifold for the next step's warm
        /// start, scaled by <paramref name="scale"/> (substeps per step: the manifold holds
        /// impulses per step).
        /// </summary>
        public static void Store(in ContactConstraint c, ContactConstraintPoint[] points, ref ContactManifold m, float scale)
        {
            for (int k = c.FirstPoint, end = c.FirstPoint + c.PointCount; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                ref ContactPoint mp = ref ContactManifold.Point(ref m, p.ManifoldPoint);
                mp.NormalImpulse = scale * p.Normal.Impulse;
                mp.TangentImpulse1 = scale * p.Tangent1.Impulse;
                mp.TangentImpulse2 = scale * p.Tangent2.Impulse;
            }
            m.RollingImpulse = c.RollingFriction > 0
                ? scale * (c.RollingImpulse1 * c.Tangent1 + c.RollingImpulse2 * c.Tangent2)
                : Vector3.Zero;
        }
    }
}
