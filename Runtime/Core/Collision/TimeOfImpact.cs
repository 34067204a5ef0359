using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Time of impact of a shape on a swept body against a fixed target (a convex core, a
    /// triangle or a half-space) by conservative advancement (Mirtich 1996): at each step the
    /// distance d can shrink by at most the sweep's motion bound per unit time, so advancing by
    /// (d - target) / bound never passes the first contact. The result stops
    /// a target gap short of touching, so the next step sees a small gap.
    /// </summary>
    internal static class TimeOfImpact
    {
        const int MaxIterations = 40;

        /// <summary>
        /// The first fraction in [0, <paramref name="tMax"/>) at which the shape
        /// (<paramref name="geometry"/> at <paramref name="localPose"/> on the sweeping body)
        /// comes within <paramref name="targetGap"/> of the target. A shape already within the
        /// gap at the start counts as hit at 0 only when the sweep drives it in by more than
        /// <paramref name="fastApproach"/> over the whole step (a body resting or sliding on a
        /// surface is not stopped).
        /// </summary>
        public static bool Compute(in ShapeGeometry geometry, in Pose localPose, in BodySweep sweep, float bound,
            in SupportShape target, bool targetIsPlane, Vector3 planeNormal, float planeOffset,
            float targetGap, float tolerance, float fastApproach, float tMax, out float toi)
        {
            toi = 0;
            if (!(bound > 0)) return false;
            float t = 0;
            float d0 = Distance(geometry, sweep.BodyPose(0) * localPose, target, targetIsPlane, planeNormal, planeOffset);
            if (d0 < targetGap + tolerance)
            {
                // Touching at the start: a hit only if the motion drives into the target fast.
                float probe = MathF.Min(1f, MathF.Max(tolerance, 0.1f * fastApproach) / bound);
                float d1 = Distance(geometry, sweep.BodyPose(probe) * localPose, target, targetIsPlane, planeNormal, planeOffset);
                float approachPerStep = (d0 - d1) / probe;
                return approachPerStep > fastApproach;
            }
            float d = d0;
            for (int iteration = 0; iteration < MaxIterations; iteration++)
            {
                t += (d - targetGap) / bound;
                if (t >= tMax) return false;
                d = Distance(geometry, sweep.BodyPose(t) * localPose, target, targetIsPlane, planeNormal, planeOffset);
                if (d < targetGap + tolerance)
                {
                    toi = t;
                    return true;
                }
            }
            // Not converged (grazing): report the last safe fraction.
            toi = t;
            return true;
        }

        static float Distance(in ShapeGeometry g, in Pose pose, in SupportShape target, bool targetIsPlane, Vector3 n, float offset)
        {
            SupportShape s = SupportShape.From(g, pose);
            if (targetIsPlane) return Vector3.Dot(n, s.Support(-n, out _)) - s.Radius - offset;
            float core = Gjk.Distance(s, target, out _, out _, out _);
            // Overlapping cores: some negative number is all conservative advancement needs.
            return core <= CollisionMargins.CoreTolerance ? -s.Radius - target.Radius : core - s.Radius - target.Radius;
        }
    }
}
