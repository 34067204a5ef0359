using System;
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The pair of one-sided limit rows a joint keeps on one coordinate (a hinge's angle, a
    /// slider's travel, a distance joint's length, a cone-twist's twist): the lower row pushes
    /// the coordinate up, along the row's direction, the upper row pushes it down, along the
    /// opposite one. Each joint decides when a row is active and solves its velocity rows itself
    /// (the joint trees take some over); the setup, warm start and position pass are the same
    /// for every joint and are written here once. The rows stay separate fields of each joint's
    /// parts, whose layout the world state records.
    /// </summary>
    internal static class JointLimits
    {
        /// <summary>Angular rows about unit <paramref name="u"/>: the lower limit's about u, the upper's about -u.</summary>
        public static void SetAngular(ref AxisConstraintPart lower, ref AxisConstraintPart upper, Vector3 u)
        {
            lower.SetAngular(u);
            upper.SetAngular(-u);
        }

        /// <summary>Linear rows along unit <paramref name="n"/> between arms <paramref name="rA"/> and <paramref name="rB"/>: the lower limit's along n, the upper's along -n.</summary>
        public static void SetLinear(ref AxisConstraintPart lower, ref AxisConstraintPart upper, Vector3 rA, Vector3 rB, Vector3 n)
        {
            lower.SetLinear(rA, rB, n);
            upper.SetLinear(rA, rB, -n);
        }

        /// <summary>Applies the accumulated impulse of each active row, lower first.</summary>
        public static void WarmStart(in AxisConstraintPart lower, in AxisConstraintPart upper, bool hasLower, bool hasUpper, ref SolverBody a, ref SolverBody b)
        {
            if (hasLower) lower.WarmStart(ref a, ref b);
            if (hasUpper) upper.WarmStart(ref a, ref b);
        }

        /// <summary>
        /// The position pass of each active row, lower first: <paramref name="aboveLower"/> is the
        /// coordinate minus the lower limit, <paramref name="belowUpper"/> the upper limit minus
        /// the coordinate; only a violation (a negative value) moves the bodies.
        /// </summary>
        public static void SolvePosition(in AxisConstraintPart lower, in AxisConstraintPart upper, bool hasLower, bool hasUpper,
            ref SolverBody a, ref SolverBody b, float aboveLower, float belowUpper, float beta, float maxC)
        {
            if (hasLower) lower.SolvePosition(ref a, ref b, MathF.Min(aboveLower, 0), beta, maxC);
            if (hasUpper) upper.SolvePosition(ref a, ref b, MathF.Min(belowUpper, 0), beta, maxC);
        }
    }
}
