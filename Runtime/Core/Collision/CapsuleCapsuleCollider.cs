using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Capsule against capsule: the closest points of the two segments give the normal and
    /// depth. When the segments are nearly parallel the capsules touch along a line, so the
    /// two ends of the overlapping stretch become two points (ids 0 and 1) and a capsule
    /// lying on another does not rock; otherwise one point (id 2).
    /// </summary>
    internal static class CapsuleCapsuleCollider
    {
        /// <summary>Sine of the largest angle at which two segments count as parallel.</summary>
        const float ParallelSine = 0.05f;

        /// <summary>Pair function: A and B are capsules.</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output)
        {
            Vector3 ea = poseA.TransformDirection(new Vector3(0, a.HalfHeight, 0));
            Vector3 eb = poseB.TransformDirection(new Vector3(0, b.HalfHeight, 0));
            Collide(poseA.Position - ea, poseA.Position + ea, a.Radius, poseB.Position - eb, poseB.Position + eb, b.Radius, output);
        }

        /// <summary>Segment a0-a1 with radius ra against segment b0-b1 with radius rb.</summary>
        public static void Collide(Vector3 a0, Vector3 a1, float ra, Vector3 b0, Vector3 b1, float rb, ContactBuffer output)
        {
            SegmentClosestPoints.Compute(a0, a1, b0, b1, out _, out _, out Vector3 ca, out Vector3 cb);
            Vector3 d = cb - ca;
            float dist = d.Length();
            if (dist - ra - rb > output.Speculative) return;

            Vector3 da = a1 - a0, db = b1 - b0;
            Vector3 n;
            if (dist > CollisionMargins.CoreTolerance) n = d / dist;
            else n = CrossingNormal(da, db, 0.5f * (b0 + b1) - 0.5f * (a0 + a1));

            output.BeginPatch(n);
            float la = da.Length(), lb = db.Length();
            if (la > 1e-6f && lb > 1e-6f && Vector3.Cross(da / la, db / lb).Length() < ParallelSine)
            {
                // The stretch of A facing B: B's ends projected on A, clamped to A.
                float sb0 = Vector3.Dot(b0 - a0, da) / (la * la);
                float sb1 = Vector3.Dot(b1 - a0, da) / (la * la);
                float lo = MathF.Max(0, MathF.Min(sb0, sb1)), hi = MathF.Min(1, MathF.Max(sb0, sb1));
                if (hi - lo > 1e-3f)
                {
                    AddAt(a0 + da * lo, b0, b1, ra, rb, n, 0, output);
                    AddAt(a0 + da * hi, b0, b1, ra, rb, n, 1, output);
                    return;
                }
            }
            float sep = dist - ra - rb;
            if (dist <= CollisionMargins.CoreTolerance) sep = -ra - rb;
            Vector3 sa = ca + n * ra;
            output.Add(sa + 0.5f * sep * n, sep, 2);
        }

        static void AddAt(Vector3 pa, Vector3 b0, Vector3 b1, float ra, float rb, Vector3 n, uint id, ContactBuffer output)
        {
            Vector3 pb = SegmentClosestPoints.OnSegment(b0, b1, pa, out _);
            float sep = Vector3.Dot(pb - pa, n) - ra - rb;
            Vector3 sa = pa + n * ra;
            output.Add(sa + 0.5f * sep * n, sep, id);
        }

        // Normal for intersecting segments: perpendicular to both (or, when parallel, to A),
        // turned to point from A's centre towards B's.
        internal static Vector3 CrossingNormal(Vector3 da, Vector3 db, Vector3 towardsB)
        {
            Vector3 n = Vector3.Cross(da, db);
            if (n.LengthSquared() < 1e-10f * MathF.Max(1e-12f, da.LengthSquared() * db.LengthSquared()))
            {
                float dd = da.LengthSquared();
                n = dd > 1e-12f ? towardsB - Vector3.Dot(towardsB, da) / dd * da : towardsB;
                if (n.LengthSquared() < 1e-12f)
                    n = dd > 1e-12f ? Vector3.Cross(da, MathF.Abs(da.X) < 0.9f * MathF.Sqrt(dd) ? Vector3.UnitX : Vector3.UnitZ) : Vector3.UnitY;
            }
            n = Vector3.Normalize(n);
            return Vector3.Dot(n, towardsB) < 0 ? -n : n;
        }
    }
}
