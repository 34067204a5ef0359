using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Which one-sided rows join the block this step: a hinge or slider on or closing on its stop,
    /// a cone-twist joint's cone and twist under a heavy load (see the class).
    /// </summary>
    internal sealed partial class JointTreeSolver
    {
        /// <summary>
        /// The angle limit a hinge rests on or closes on (+1 lower, -1 upper, 0 neither): within
        /// <see cref="LimitReach"/> of it, or closing fast enough to reach it within the step,
        /// not leaving it faster than <see cref="RestingSpin"/>, and not past it by more than the
        /// capped bias closes. Its row joins the block: speculative while the stop is ahead (the
        /// hinge may close the gap within the substep), an equality on it, and only ever pushing
        /// (a row the block would have pull is released and the block solved again, see Solve).
        /// Row by row the limit row was a spring on the light arm: a 1000 kg load on a 1 kg arm
        /// drooped 97 degrees past its stop, and swung onto it went 99 degrees through.
        /// </summary>
        static sbyte RestingLimit(in JointData j, in Softness soft, Vector3 wA, Vector3 wB, float dt)
        {
            if (!j.HasLowerLimit && !j.HasUpperLimit) return 0;
            float spin = Vector3.Dot(wB - wA, Vector3.Transform(Vector3.UnitX, j.FrameA));
            float angle = JointSolver.TwistAngle(j.FrameA, j.FrameB);
            if (j.HasLowerLimit && spin <= RestingSpin && angle - j.Lower <= LimitReach + MathF.Max(0, -spin) * dt
                && soft.BiasRate * (j.Lower - angle) <= soft.MaxBias) return 1;
            if (j.HasUpperLimit && spin >= -RestingSpin && j.Upper - angle <= LimitReach + MathF.Max(0, spin) * dt
                && soft.BiasRate * (angle - j.Upper) <= soft.MaxBias) return -1;
            return 0;
        }

        /// <summary>The fastest a hinge may turn away from a limit and still count as on it, rad/s: 0.2.</summary>
        const float RestingSpin = 0.2f;

        /// <summary>How close to an angle limit a hinge counts as resting on it, rad: 0.005 (0.3 degrees).</summary>
        const float LimitReach = 0.005f;

        /// <summary>
        /// The slide limit a prismatic joint rests on or closes on (+1 lower, -1 upper, 0 neither),
        /// as <see cref="RestingLimit"/> for a hinge: within <see cref="SlideReach"/> of it or closing
        /// fast enough to reach it within the step, and not past it by more than the capped bias
        /// closes. Its row joins the block as the hinge's stop does, scaled as the rows across the
        /// axis are (rigid among them, a 1000 kg load that struck the limit was thrown back 0.2 m).
        /// Also while it is being left: the block releases a row that would pull, where row by row
        /// the accumulated impulse that held the load, warm-started on the light carriage, threw a
        /// 1000 kg load thrown up at 1 m/s to 159 mm instead of 51. Row by row the limit row was a
        /// spring on the light carriage: a 1000 kg load welded under a 1 kg carriage on a vertical
        /// rail sat 69 mm past its lower limit, and 1e5 kg fell through it.
        /// </summary>
        static sbyte RestingSlide(in JointData j, in Softness soft, Vector3 vA, Vector3 vB, Vector3 gap, float dt)
        {
            if (!j.HasLowerLimit && !j.HasUpperLimit) return 0;
            Vector3 axis = Vector3.Transform(Vector3.UnitX, j.FrameA);
            float speed = Vector3.Dot(axis, vB - vA), at = Vector3.Dot(axis, gap);
            if (j.HasLowerLimit && at - j.Lower <= SlideReach + MathF.Max(0, -speed) * dt
                && soft.BiasRate * (j.Lower - at) <= soft.MaxBias) return 1;
            if (j.HasUpperLimit && j.Upper - at <= SlideReach + MathF.Max(0, speed) * dt
                && soft.BiasRate * (at - j.Upper) <= soft.MaxBias) return -1;
            return 0;
        }

        /// <summary>How close to a slide limit a prismatic joint counts as resting on it, m: 0.005.</summary>
        const float SlideReach = 0.005f;

        /// <summary>
        /// Which limits of a cone-twist joint the block takes this step (bits: <see cref="ConeRow"/>,
        /// <see cref="TwistLowerRow"/>, <see cref="TwistUpperRow"/>): each one the joint rests on or
        /// closes on, as a slider's limit (<see cref="RestingSlide"/>): within <see cref="LimitReach"/>
        /// of it or closing fast enough to reach it within the step, and not past it by more than
        /// the capped bias closes; also while it is being left (the block releases a row that
        /// would pull; a spin test as the hinge's let a 1 kg arm's momentary spin under 1e5 kg,
        /// cone and twist both held, drop the twist row, and the arm tore loose). Their rows (about
        /// the swing axis and the mean twist axis, as ConeTwistJointSolver's) join the block, scaled
        /// as the anchor rows, speculative while ahead, pushing only. Row by row each was a spring on
        /// the light arm: a 1000 kg load on a 1 kg arm resting on a 30 degree cone swung through it
        /// to 170 degrees, a twist limit of 10 degrees let it turn to 144, and under 1e5 kg the
        /// anchor gave way (the load fell 73 m).
        /// </summary>
        static sbyte RestingCone(in JointData j, in Softness soft, Vector3 wA, Vector3 wB, float dt)
        {
            int rows = 0;
            if (j.ConeAngle < MathF.PI)
            {
                ConeSwing(j.FrameA, j.FrameB, out Vector3 axis, out float swing);
                float rate = Vector3.Dot(axis, wB - wA);
                if (j.ConeAngle - swing <= LimitReach + MathF.Max(0, rate) * dt
                    && soft.BiasRate * (swing - j.ConeAngle) <= soft.MaxBias) rows |= ConeRow;
            }
            // The twist limits about the mean twist axis, as the hinge's stops about its axis; not
            // near a half-turn swing, where that axis (the frames' x axes summed) vanishes and
            // turns over: a 1e5 kg pendulum on a 1 kg link swinging through it tore loose.
            Vector3 sum = Vector3.Transform(Vector3.UnitX, j.FrameA) + Vector3.Transform(Vector3.UnitX, j.FrameB);
            if (j.TwistAngle < MathF.PI && sum.LengthSquared() > TwistAxisFloor)
            {
                Vector3 t = TwistAxis(j.FrameA, j.FrameB);
                float spin = Vector3.Dot(t, wB - wA), twist = JointSolver.TwistAngle(j.FrameA, j.FrameB);
                if (twist + j.TwistAngle <= LimitReach + MathF.Max(0, -spin) * dt
                    && soft.BiasRate * (-j.TwistAngle - twist) <= soft.MaxBias) rows |= TwistLowerRow;
                else if (j.TwistAngle - twist <= LimitReach + MathF.Max(0, spin) * dt
                    && soft.BiasRate * (twist - j.TwistAngle) <= soft.MaxBias) rows |= TwistUpperRow;
            }
            return (sbyte)rows;
        }

        /// <summary>
        /// The least squared length of the frames' x axes summed (4 cos^2(swing / 2)) at which a
        /// twist limit joins the block: 1, a swing of 120 degrees.
        /// </summary>
        const float TwistAxisFloor = 1f;

        /// <summary>
        /// Bits of a cone-twist joint's <see cref="JointData.DirectLimit"/>: the block holds its cone,
        /// its lower or its upper twist limit this step; TreeLimits: the block takes its limits as
        /// it meets them (the joint leaves a limit still ahead to the block, as a tree hinge its stop).
        /// </summary>
        const int ConeRow = 1, TwistLowerRow = 2, TwistUpperRow = 4, TreeLimits = 8;

        /// <summary>A cone-twist joint's twist axis (as ConeTwistJointSolver's): the mean of the frames' x axes.</summary>
        static Vector3 TwistAxis(Quaternion fA, Quaternion fB)
        {
            Vector3 ta = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 t = ta + Vector3.Transform(Vector3.UnitX, fB);
            float length = t.Length();
            return length > 1e-6f ? t / length : ta;
        }

        /// <summary>
        /// A cone-twist joint's swing (as ConeTwistJointSolver measures it): the angle between the
        /// frames' x axes, and the unit axis about which it grows (A's y axis when they are aligned).
        /// </summary>
        static void ConeSwing(Quaternion fA, Quaternion fB, out Vector3 axis, out float swing)
        {
            Vector3 ta = Vector3.Transform(Vector3.UnitX, fA), tb = Vector3.Transform(Vector3.UnitX, fB);
            Vector3 s = Vector3.Cross(ta, tb);
            float sin = s.Length();
            swing = MathF.Atan2(sin, Vector3.Dot(ta, tb));
            axis = sin > 1e-6f ? s / sin : Vector3.Transform(Vector3.UnitY, fA);
        }

        /// <summary>
        /// A rope (a distance joint with min &lt; max) joins the block while it is pulled taut: its
        /// length within 1 % of its maximum (or beyond it), with an upper limit. The block holds it
        /// as an equality at the maximum whose accumulated impulse may only pull (clamped at zero;
        /// a rope that goes slack in the step pushes nothing, and the next step leaves it out).
        /// Row by row, a 1000 kg load on five 1 kg links joined by 0.1 m ropes stretched them
        /// 0.73 m and 1e5 kg fell 108 m: the limit row is a spring on the light link's mass,
        /// as the anchor rows were.
        /// </summary>
        static bool Taut(in JointData j)
        {
            if (!j.HasUpperLimit) return false;
            float length = (j.DeltaCenter + j.ArmB - j.ArmA).Length();
            return length >= 0.99f * j.MaxLength;
        }

        /// <summary>
        /// How much heavier than the lighter body of a cone-twist joint the load it carries must
        /// be for the block to take the joint's cone and twist limits: 4.
        /// </summary>
        const float LimitMassRatio = 4f;

        // The cone and twist limits of the tree whose nodes are _order[first .. end) (pre-order)
        // stay in the block only where the joint carries a load several times its lighter body's
        // mass: row by row a limit is a spring on that body's own inertia, so a 1 kg arm under
        // 1000 kg went through its cone, and under 10-29 kg it overshot its 30 degree cone to
        // 35-45 degrees (TGS) or 65-170 (PGS) and its 10 degree twist limit to 27-38 (TGS) or
        // 75-93 (PGS); while between bodies of like mass the rows hold, and in the block they kept
        // a ragdoll pile from settling (awake after 15 s, where row by row it sleeps within
        // 3.1 s): the limits the block takes are not held by joint friction in the same pass.
        // The load a joint carries: everything on its far side from the world, in a tree hung
        // from a world anchor; in a free tree, the lighter of its two sides (a ragdoll's: 1.0-2.3
        // times the joint's lighter part, so its limits stay in the rows).
        void GateLimits(SolverBody[] bodies, JointData[] data, int first, int end)
        {
            // Subtree masses, children before parents (reverse pre-order).
            for (int k = first; k < end; k++) _subtreeMass[_order[k]] = 0f;
            for (int k = end - 1; k >= first; k--)
            {
                int node = _order[k];
                if (_joint[node] < 0) _subtreeMass[node] += 1f / bodies[_body[node]].InverseMass;
                if (_parent[node] >= 0) _subtreeMass[_parent[node]] += _subtreeMass[node];
            }
            int root = _order[first];
            bool anchored = _joint[root] >= 0;
            float total = _subtreeMass[root];
            for (int k = first; k < end; k++)
            {
                int node = _order[k];
                if (_joint[node] < 0) continue;
                ref JointData j = ref data[_joint[node]];
                if (j.Kind != JointKind.ConeTwist) continue;
                float lighter = float.MaxValue;
                if (_nodeA[node] >= 0) lighter = 1f / bodies[_body[_nodeA[node]]].InverseMass;
                if (_nodeB[node] >= 0) lighter = MathF.Min(lighter, 1f / bodies[_body[_nodeB[node]]].InverseMass);
                float carried = anchored ? _subtreeMass[node] : MathF.Min(_subtreeMass[node], total - _subtreeMass[node]);
                if (carried >= LimitMassRatio * lighter) continue;
                j.DirectLimit = 0;
                _rows[node] = JointKind.Ball;
                _dim[node] = 3;
            }
        }
    }
}
