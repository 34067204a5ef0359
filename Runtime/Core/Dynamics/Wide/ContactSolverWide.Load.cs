#if NET
using System;
using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Dynamics
{
    // Transposing prepared scalar constraints into lanes (the lane layout of WideContact and
    // WideImpact), apart from the contact math in Contacts/ContactSolverWide.cs.
    internal static partial class ContactSolverWide
    {
        /// <summary>
        /// Transposes the prepared constraints <paramref name="source"/>[i] into lanes of
        /// <paramref name="w"/> and <paramref name="impact"/>; unused lanes get the fixed body
        /// and inert rows. <paramref name="laneSlots"/> gets, per lane and slot, the point's
        /// index in its manifold.
        /// </summary>
        public static void Load(ref WideContact w, ref WideImpact impact, int[] laneBodies, int groupOffset, ReadOnlySpan<int> source,
            ContactConstraint[] contacts, ContactConstraintPoint[] points, ContactManifold[] manifolds, int[] laneSlots)
        {
            int width = Width;
            // Every field of a used lane is written below: only padding lanes need the clear.
            if (source.Length < width)
            {
                w = default;
                impact = default;
            }
            w.Loaded = Vector<int>.Zero;
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
                LoadPoint(ref w.P0, ref impact.P0, lane, points[c.Block0.I]);
                LoadPoint(ref w.P1, ref impact.P1, lane, points[c.Block0.J]);
                LoadPoint(ref w.P2, ref impact.P2, lane, points[c.Block1.I]);
                LoadPoint(ref w.P3, ref impact.P3, lane, points[c.Block1.J]);
                laneSlots[4 * at] = points[c.Block0.I].ManifoldPoint;
                laneSlots[4 * at + 1] = points[c.Block0.J].ManifoldPoint;
                laneSlots[4 * at + 2] = points[c.Block1.I].ManifoldPoint;
                laneSlots[4 * at + 3] = points[c.Block1.J].ManifoldPoint;
                WideVector3.Lane(ref w.K11a, lane) = c.Block0.K11;
                WideVector3.Lane(ref w.K12a, lane) = c.Block0.K12;
                WideVector3.Lane(ref w.K22a, lane) = c.Block0.K22;
                WideVector3.Lane(ref w.K11b, lane) = c.Block1.K11;
                WideVector3.Lane(ref w.K12b, lane) = c.Block1.K12;
                WideVector3.Lane(ref w.K22b, lane) = c.Block1.K22;
                w.Normal.Set(lane, c.Normal);
                WideVector3.Lane(ref w.Friction, lane) = c.Friction;
                WideVector3.Lane(ref impact.Restitution, lane) = c.Restitution;
                // The friction rows' centroid, summed as ContactSolver.Prepare sums it.
                ref ContactManifold m = ref manifolds[c.Manifold];
                Vector3 centroidA = Vector3.Zero, centroidB = Vector3.Zero;
                for (int i = 0; i < 4; i++)
                {
                    centroidA += ContactManifold.Point(ref m, i).AnchorA;
                    centroidB += ContactManifold.Point(ref m, i).AnchorB;
                }
                w.CentroidA.Set(lane, centroidA * 0.25f);
                w.CentroidB.Set(lane, centroidB * 0.25f);
                WideVector3.Lane(ref w.FrictionMass1, lane) = c.Friction1.EffectiveMass;
                WideVector3.Lane(ref w.FrictionMass2, lane) = c.Friction2.EffectiveMass;
                WideVector3.Lane(ref w.FrictionImpulse1, lane) = c.Friction1.Impulse;
                WideVector3.Lane(ref w.FrictionImpulse2, lane) = c.Friction2.Impulse;
                WideVector3.Lane(ref w.TwistMass, lane) = c.TwistMass;
                WideVector3.Lane(ref w.TwistImpulse, lane) = c.TwistImpulse;
                WideVector3.Lane(ref w.TwistRadius, lane) = c.TwistRadius;
            }
        }

        static void LoadPoint(ref WidePoint p, ref WideImpactPoint i, int lane, in ContactConstraintPoint s)
        {
            p.AngularA.Set(lane, s.Normal.AngularA);
            p.AngularB.Set(lane, s.Normal.AngularB);
            WideVector3.Lane(ref p.Separation, lane) = s.Separation;
            WideVector3.Lane(ref p.Impulse, lane) = s.Normal.Impulse;
            WideVector3.Lane(ref i.EffectiveMass, lane) = s.Normal.EffectiveMass;
            WideVector3.Lane(ref i.RelativeVelocity, lane) = s.RelativeVelocity;
            WideVector3.Lane(ref i.Applied, lane) = 0;
            WideVector3.Lane(ref i.LastSubstep, lane) = 0;
        }
    }
}
#endif
