using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Capsule (A) against box (B), in the box frame. When the capsule's segment stays outside
    /// the box, GJK gives the closest points; when the closest box point lies inside a face,
    /// the segment is clipped to that face's rectangle and both ends of the clipped stretch
    /// become points (a capsule lying on a box gets two). When the segment enters the box, a
    /// separating axis test over the 3 face normals and the 3 segment-edge cross products
    /// finds the least-penetration axis: a face gives the clipped pair of points, an edge one
    /// point between the segment and that box edge.
    /// </summary>
    internal static class CapsuleBoxCollider
    {
        /// <summary>Pair function: A is a capsule, B a box.</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output)
        {
            Vector3 axis = poseA.TransformDirection(new Vector3(0, a.HalfHeight, 0));
            Vector3 p0 = poseB.InverseTransformPoint(poseA.Position - axis);
            Vector3 p1 = poseB.InverseTransformPoint(poseA.Position + axis);
            Collide(p0, p1, a.Radius, b.HalfExtents, poseB, output);
        }

        /// <summary>Segment p0-p1 (box frame) with radius r against a box of half-extents h at <paramref name="boxPose"/>.</summary>
        public static void Collide(Vector3 p0, Vector3 p1, float r, Vector3 h, in Pose boxPose, ContactBuffer output)
        {
            var segment = SupportShape.Capsule(p0, p1, 0);
            var box = new SupportShape { Kind = SupportKind.Box, Axes = Mat3.Identity, Extent = h };
            float dist = Gjk.Distance(segment, box, out Vector3 onSegment, out Vector3 onBox, out _);
            float speculative = output.Speculative;

            if (dist > CollisionMargins.CoreTolerance)
            {
                if (dist - r > speculative) return;
                Vector3 n = (onSegment - onBox) / dist;            // box -> capsule
                int face = FaceOfPoint(onBox, h);
                if (face >= 0)
                {
                    // The box point is inside a face: n is that face's normal.
                    int k = face >> 1;
                    Vector3 fn = FaceNormal(face);
                    output.BeginPatch(-boxPose.TransformDirection(fn));
                    if (AddClipped(p0, p1, r, h, k, fn, face, boxPose, output)) return;
                    output.BeginPatch(-boxPose.TransformDirection(n));
                }
                else output.BeginPatch(-boxPose.TransformDirection(n));
                float sep = dist - r;
                Vector3 mid = onBox + n * (0.5f * sep);
                output.Add(boxPose.TransformPoint(mid), sep, 0x100);
                return;
            }

            // The segment enters the box: least-penetration axis.
            Vector3 d = p1 - p0;
            float best = float.MinValue;
            int bestAxis = -1;
            Vector3 bestN = default;
            for (int k = 0; k < 6; k++)
            {
                Vector3 l;
                if (k < 3) l = k == 0 ? Vector3.UnitX : k == 1 ? Vector3.UnitY : Vector3.UnitZ;
                else
                {
                    Vector3 e = k == 3 ? Vector3.UnitX : k == 4 ? Vector3.UnitY : Vector3.UnitZ;
                    l = Vector3.Cross(d, e);
                    float len = l.Length();
                    if (len < 1e-4f * MathF.Max(1e-6f, d.Length())) continue;
                    l /= len;
                }
                float boxR = h.X * MathF.Abs(l.X) + h.Y * MathF.Abs(l.Y) + h.Z * MathF.Abs(l.Z);
                float s0 = Vector3.Dot(p0, l), s1 = Vector3.Dot(p1, l);
                float segMin = MathF.Min(s0, s1) - r, segMax = MathF.Max(s0, s1) + r;
                float above = segMin - boxR, below = -boxR - segMax;
                float sep = MathF.Max(above, below);
                if (sep > speculative) return;
                // Edge axes must beat faces clearly; faces keep their features stable.
                float bias = k < 3 ? 0 : 1e-3f;
                if (sep > best + bias)
                {
                    best = sep;
                    bestAxis = k;
                    bestN = above >= below ? l : -l;
                }
            }
            if (bestAxis < 3)
            {
                int k = bestAxis;
                float c = k == 0 ? bestN.X : k == 1 ? bestN.Y : bestN.Z;
                int face = 2 * k + (c > 0 ? 0 : 1);
                Vector3 fn = FaceNormal(face);
                output.BeginPatch(-boxPose.TransformDirection(fn));
                if (AddClipped(p0, p1, r, h, k, fn, face, boxPose, output)) return;
                // The segment pokes in beside the face rectangle: its deepest end.
                float hk = k == 0 ? h.X : k == 1 ? h.Y : h.Z;
                Vector3 deep = Vector3.Dot(p0, fn) < Vector3.Dot(p1, fn) ? p0 : p1;
                float sepDeep = Vector3.Dot(deep, fn) - hk - r;
                output.Add(boxPose.TransformPoint(deep - fn * (r + 0.5f * sepDeep)), sepDeep, 0x100);
                return;
            }
            {
                int k = bestAxis - 3;
                Vector3 n = bestN;
                Vector3 center = new Vector3(
                    k == 0 ? 0 : MathF.Sign(n.X) * h.X,
                    k == 1 ? 0 : MathF.Sign(n.Y) * h.Y,
                    k == 2 ? 0 : MathF.Sign(n.Z) * h.Z);
                Vector3 e = k == 0 ? new Vector3(h.X, 0, 0) : k == 1 ? new Vector3(0, h.Y, 0) : new Vector3(0, 0, h.Z);
                SegmentClosestPoints.Compute(p0, p1, center - e, center + e, out _, out _, out Vector3 qs, out Vector3 qe);
                float sep = Vector3.Dot(qs - qe, n) - r;
                uint signs = (uint)((n.X > 0 ? 1 : 0) | (n.Y > 0 ? 2 : 0) | (n.Z > 0 ? 4 : 0));
                output.BeginPatch(-boxPose.TransformDirection(n));
                output.Add(boxPose.TransformPoint(qe + n * (0.5f * sep)), sep, 0x200u | ((uint)k << 4) | signs);
            }
        }

        // Clips the segment to face "face" (axis k) and adds its two ends; false when the
        // segment misses the face rectangle.
        static bool AddClipped(Vector3 p0, Vector3 p1, float r, Vector3 h, int k, Vector3 fn, int face, in Pose boxPose, ContactBuffer output)
        {
            float lo = 0, hi = 1;
            Vector3 d = p1 - p0;
            for (int m = 0; m < 3 && lo <= hi; m++)
            {
                if (m == k) continue;
                if (!Slab.Cross(p0, d, h, m, 1e-9f, out float t0, out float t1, out _)) return false;
                lo = MathF.Max(lo, t0);
                hi = MathF.Min(hi, t1);
            }
            if (lo > hi) return false;
            float hk = k == 0 ? h.X : k == 1 ? h.Y : h.Z;
            AddEnd(p0 + d * lo, r, hk, fn, (uint)(face << 4), boxPose, output);
            if (hi - lo > 1e-4f) AddEnd(p0 + d * hi, r, hk, fn, (uint)(face << 4) | 1u, boxPose, output);
            return true;
        }

        static void AddEnd(Vector3 p, float r, float hk, Vector3 fn, uint id, in Pose boxPose, ContactBuffer output)
        {
            float sep = Vector3.Dot(p, fn) - hk - r;
            Vector3 onCapsule = p - fn * r;
            output.Add(boxPose.TransformPoint(onCapsule - fn * (0.5f * sep)), sep, id);
        }

        // Face index 2k (+axis k) or 2k + 1 (-axis k) when the box point lies on exactly one
        // face (not on an edge); -1 otherwise.
        static int FaceOfPoint(Vector3 q, Vector3 h)
        {
            const float tol = 1e-5f;
            int face = -1, count = 0;
            for (int k = 0; k < 3; k++)
            {
                float c = k == 0 ? q.X : k == 1 ? q.Y : q.Z;
                float hk = k == 0 ? h.X : k == 1 ? h.Y : h.Z;
                if (c >= hk - tol * (1 + hk)) { face = 2 * k; count++; }
                else if (c <= -hk + tol * (1 + hk)) { face = 2 * k + 1; count++; }
            }
            return count == 1 ? face : -1;
        }

        static Vector3 FaceNormal(int face)
        {
            float s = (face & 1) == 0 ? 1f : -1f;
            int k = face >> 1;
            return k == 0 ? new Vector3(s, 0, 0) : k == 1 ? new Vector3(0, s, 0) : new Vector3(0, 0, s);
        }
    }
}
