using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Any convex pair, by GJK on the cores (separated) or EPA (cores overlap), then a
    /// manifold from the features facing each other along the normal: when one shape presents
    /// a face nearly perpendicular to the normal, the other's facing feature (face, segment or
    /// point) is clipped against that reference face's side planes and each clipped point is
    /// measured along the face normal; otherwise the single pair of closest points is used.
    /// This is the fallback for every convex pair without a dedicated function and the path
    /// for convex hulls.
    /// </summary>
    internal static class ConvexCollider
    {
        /// <summary>Cosine above which a face counts as facing the normal (about 8 degrees).</summary>
        const float FaceCosine = 0.99f;
        const int MaxFaceVertices = 64;
        /// <summary>How much shallower than the true separation a clipped manifold may be, metres.</summary>
        const float ClipTolerance = 1e-4f;

        /// <summary>Pair function: any two convex shapes (sphere, box, capsule, hull).</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output) =>
            Collide(SupportShape.From(a, poseA), SupportShape.From(b, poseB), output);

        /// <summary>Two convex cores with radii.</summary>
        public static void Collide(in SupportShape a, in SupportShape b, ContactBuffer output)
        {
            float rA = a.Radius, rB = b.Radius;
            float dist = Gjk.Distance(a, b, out Vector3 pa, out Vector3 pb, out Simplex simplex);
            Vector3 n;
            float coreSeparation;
            if (dist > CollisionMargins.CoreTolerance)
            {
                if (dist - rA - rB > output.Speculative) return;
                n = (pb - pa) / dist;
                coreSeparation = dist;
            }
            else if (Epa.Penetration(a, b, simplex, out n, out float depth, out pa, out pb))
            {
                coreSeparation = -depth;
            }
            else
            {
                n = FallbackNormal(a, b);
                coreSeparation = 0;
            }
            if (coreSeparation - rA - rB > output.Speculative) return;
            Manifold(a, b, n, coreSeparation, pa, output);
        }

        /// <summary>
        /// The manifold of two cores given the normal from A to B, the core separation along it
        /// and the closest point on A's core: face clipping when a face faces the normal,
        /// else the single pair of closest points.
        /// </summary>
        public static void Manifold(in SupportShape a, in SupportShape b, Vector3 n, float coreSeparation, Vector3 pa, ContactBuffer output)
        {
            float rA = a.Radius, rB = b.Radius;
            Span<Vector3> fa = stackalloc Vector3[MaxFaceVertices];
            Span<Vector3> fb = stackalloc Vector3[MaxFaceVertices];
            int ca = a.SupportFace(n, fa, out Vector3 na, out int ida);
            int cb = b.SupportFace(-n, fb, out Vector3 nb, out int idb);
            float alignA = ca >= 3 ? Vector3.Dot(na, n) : -1;
            float alignB = cb >= 3 ? -Vector3.Dot(nb, n) : -1;
            int pointsBefore = output.PointCount, patchesBefore = output.PatchCount;
            float sep = coreSeparation - rA - rB;
            if (alignA >= FaceCosine && alignA + 1e-3f >= alignB)
                Clip(fa.Slice(0, ca), na, rA, ida, fb.Slice(0, cb), rB, idb, false, output);
            else if (alignB >= FaceCosine)
                Clip(fb.Slice(0, cb), nb, rB, idb, fa.Slice(0, ca), rA, ida, true, output);
            if (output.PointCount > pointsBefore)
            {
                // Measured along a face normal up to 8 degrees off the true one, the clipped
                // points can miss the closest approach (an edge next to the face): then the
                // closest points alone are the honest answer.
                float clippedMin = float.MaxValue;
                for (int i = pointsBefore; i < output.PointCount; i++) clippedMin = MathF.Min(clippedMin, output.Separation[i]);
                if (clippedMin <= sep + ClipTolerance) return;
                output.Truncate(pointsBefore, patchesBefore);
            }
            output.BeginPatch(n);
            output.Add(pa + n * (rA + 0.5f * sep), sep, 0x7FFF0000u);
        }

        // Clips the incident feature against the reference polygon's side planes; each kept
        // point's separation is measured along the reference normal.
        static void Clip(ReadOnlySpan<Vector3> reference, Vector3 nr, float rRef, int refId,
            ReadOnlySpan<Vector3> incident, float rInc, int incId, bool referenceIsB, ContactBuffer output)
        {
            int m = reference.Length;
            Span<Vector3> planeN = stackalloc Vector3[MaxFaceVertices];
            Span<float> planeD = stackalloc float[MaxFaceVertices];
            for (int i = 0; i < m; i++)
            {
                Vector3 p = reference[i], q = reference[i + 1 == m ? 0 : i + 1];
                Vector3 side = Vector3.Cross(q - p, nr);
                float len = side.Length();
                side = len > 1e-12f ? side / len : Vector3.Zero;
                planeN[i] = side;
                planeD[i] = Vector3.Dot(side, p);
            }
            float refOffset = Vector3.Dot(nr, reference[0]);
            uint idBase = (referenceIsB ? 1u << 31 : 0) | ((uint)(refId & 0xFF) << 23) | ((uint)(incId & 0x7F) << 16);
            output.BeginPatch(referenceIsB ? -nr : nr);

            if (incident.Length >= 3)
            {
                int cap = 2 * MaxFaceVertices;
                Span<Vector3> pts = stackalloc Vector3[cap];
                Span<uint> keys = stackalloc uint[cap];
                Span<uint> segs = stackalloc uint[cap];
                Span<Vector3> sp = stackalloc Vector3[cap];
                Span<uint> sk = stackalloc uint[cap];
                Span<uint> ss = stackalloc uint[cap];
                int count = Math.Min(incident.Length, MaxFaceVertices);
                for (int i = 0; i < count; i++)
                {
                    pts[i] = incident[i];
                    keys[i] = (uint)i;
                    segs[i] = (uint)i;
                }
                count = PolygonClipper.Clip(pts, keys, segs, count, planeN.Slice(0, m), planeD.Slice(0, m), sp, sk, ss);
                for (int i = 0; i < count; i++) AddPoint(pts[i], nr, refOffset, rRef, rInc, idBase | (keys[i] & 0xFFFF), output);
                return;
            }
            if (incident.Length == 2)
            {
                Vector3 p0 = incident[0], d = incident[1] - incident[0];
                float lo = 0, hi = 1;
                uint loKey = 0, hiKey = 1;
                for (int i = 0; i < m && lo <= hi; i++)
                {
                    float dp = Vector3.Dot(planeN[i], p0) - planeD[i];
                    float dd = Vector3.Dot(planeN[i], d);
                    if (MathF.Abs(dd) < 1e-12f)
                    {
                        if (dp > 0) return;
                        continue;
                    }
                    float t = -dp / dd;
                    if (dd > 0) { if (t < hi) { hi = t; hiKey = 0x8000u | (uint)i; } }
                    else if (t > lo) { lo = t; loKey = 0x8100u | (uint)i; }
                }
                if (lo > hi) return;
                AddPoint(p0 + d * lo, nr, refOffset, rRef, rInc, idBase | loKey, output);
                if (hi - lo > 1e-4f) AddPoint(p0 + d * hi, nr, refOffset, rRef, rInc, idBase | hiKey, output);
                return;
            }
            for (int i = 0; i < m; i++)
                if (Vector3.Dot(planeN[i], incident[0]) > planeD[i]) return;
            AddPoint(incident[0], nr, refOffset, rRef, rInc, idBase, output);
        }

        static void AddPoint(Vector3 p, Vector3 nr, float refOffset, float rRef, float rInc, uint id, ContactBuffer output)
        {
            float sep = Vector3.Dot(nr, p) - refOffset - rRef - rInc;
            Vector3 incidentSurface = p - nr * rInc;
            output.Add(incidentSurface - nr * (0.5f * sep), sep, id);
        }

        // Cores that touch or cross with no volume to expand (point or segment pairs).
        static Vector3 FallbackNormal(in SupportShape a, in SupportShape b)
        {
            Vector3 towards = b.Center - a.Center;
            Vector3 da = a.Kind == SupportKind.Segment ? a.B - a.A : Vector3.Zero;
            Vector3 db = b.Kind == SupportKind.Segment ? b.B - b.A : Vector3.Zero;
            if (da != Vector3.Zero || db != Vector3.Zero)
                return CapsuleCapsuleCollider.CrossingNormal(da != Vector3.Zero ? da : db, db != Vector3.Zero ? db : da, towards);
            return towards.LengthSquared() > 1e-12f ? Vector3.Normalize(towards) : Vector3.UnitY;
        }
    }
}
