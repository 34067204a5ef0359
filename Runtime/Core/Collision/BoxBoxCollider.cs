using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Box against box by the separating axis test over the 15 candidate axes (3 face normals
    /// of each box and the 9 cross products of their edge directions; Gottschalk, Lin and
    /// Manocha, "OBBTree", 1996). The axis of largest separation decides the contact:
    /// <list type="bullet">
    /// <item>a face axis: the incident face of the other box (the one most anti-parallel to the
    /// reference normal) is clipped against the side planes of the reference face, giving up
    /// to 8 points, reduced to 4;</item>
    /// <item>an edge pair: one point, the closest points of the two supporting edges.</item>
    /// </list>
    /// Faces win over edges, and A's faces over B's, unless the other is better by a small
    /// tolerance, so a resting box keeps the same features (and feature ids) step after step.
    /// </summary>
    internal static class BoxBoxCollider
    {
        /// <summary>Pair function: A and B are boxes.</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output) =>
            Collide(poseA.Position, Mat3.FromQuaternion(poseA.Rotation), a.HalfExtents,
                    poseB.Position, Mat3.FromQuaternion(poseB.Rotation), b.HalfExtents, output);

        /// <summary>Box A (centre, rotation, half-extents) against box B.</summary>
        public static void Collide(Vector3 centerA, in Mat3 rotA, Vector3 hA, Vector3 centerB, in Mat3 rotB, Vector3 hB, ContactBuffer output)
        {
            Vector3 d = centerB - centerA;
            float speculative = output.Speculative;
            // Everything in A's frame: C = RA^T RB (B's axes seen from A), Gottschalk's
            // projections, no normalisation except for the edge axes' lengths.
            Span<float> c = stackalloc float[9];
            Span<float> ac = stackalloc float[9];
            for (int i = 0; i < 3; i++)
            {
                Vector3 ai = Axis(rotA, i);
                for (int j = 0; j < 3; j++)
                {
                    float v = Vector3.Dot(ai, Axis(rotB, j));
                    c[3 * i + j] = v;
                    ac[3 * i + j] = MathF.Abs(v) + 1e-6f;
                }
            }
            Vector3 dA = rotA.TransposeMultiply(d), dB = rotB.TransposeMultiply(d);

            float bestFaceA = float.MinValue; int faceA = 0;
            for (int i = 0; i < 3; i++)
            {
                float s = MathF.Abs(Comp(dA, i)) - Comp(hA, i) - (hB.X * ac[3 * i] + hB.Y * ac[3 * i + 1] + hB.Z * ac[3 * i + 2]);
                if (s > speculative) return;
                if (s > bestFaceA) { bestFaceA = s; faceA = i; }
            }
            float bestFaceB = float.MinValue; int faceB = 0;
            for (int j = 0; j < 3; j++)
            {
                float s = MathF.Abs(Comp(dB, j)) - Comp(hB, j) - (hA.X * ac[j] + hA.Y * ac[3 + j] + hA.Z * ac[6 + j]);
                if (s > speculative) return;
                if (s > bestFaceB) { bestFaceB = s; faceB = j; }
            }
            float bestEdge = float.MinValue; int edgeA = 0, edgeB = 0;
            for (int i = 0; i < 3; i++)
            {
                int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
                for (int j = 0; j < 3; j++)
                {
                    int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
                    // L = a_i x b_j; |L| = sqrt(1 - C_ij^2).
                    float len = MathF.Sqrt(c[3 * i1 + j] * c[3 * i1 + j] + c[3 * i2 + j] * c[3 * i2 + j]);
                    // Near-parallel edges: the face axes already cover this direction.
                    if (len < 1e-3f) continue;
                    float dist = MathF.Abs(Comp(dA, i2) * c[3 * i1 + j] - Comp(dA, i1) * c[3 * i2 + j]);
                    float ra = Comp(hA, i1) * ac[3 * i2 + j] + Comp(hA, i2) * ac[3 * i1 + j];
                    float rb = Comp(hB, j1) * ac[3 * i + j2] + Comp(hB, j2) * ac[3 * i + j1];
                    float s = (dist - ra - rb) / len;
                    if (s > speculative) return;
                    if (s > bestEdge) { bestEdge = s; edgeA = i; edgeB = j; }
                }
            }

            float scale = MathF.Min(MinComp(hA), MinComp(hB));
            float faceTolerance = 0.0005f + 0.005f * scale;
            float edgeTolerance = 0.001f + 0.01f * scale;
            bool useB = bestFaceB > bestFaceA + faceTolerance;
            float bestFace = useB ? bestFaceB : bestFaceA;
            if (bestEdge > bestFace + edgeTolerance)
                EdgeContact(centerA, rotA, hA, centerB, rotB, hB, edgeA, edgeB, output);
            else
            {
                int before = output.PointCount;
                // In coordinates centred on the reference box: far from the origin (a box 35 m
                // up a tower) world coordinates round to micrometres, and a separation taken as
                // the difference of two such numbers would carry that noise into the contact.
                if (useB) FaceContact(centerB, -d, rotB, hB, rotA, hA, faceB, true, output);
                else FaceContact(centerA, d, rotA, hA, rotB, hB, faceA, false, output);
                // Crossed edges within the tolerance can clip to nothing: take the edge pair.
                if (output.PointCount == before && bestEdge > float.MinValue)
                    EdgeContact(centerA, rotA, hA, centerB, rotB, hB, edgeA, edgeB, output);
            }
        }

        // cI: the incident box's centre relative to the reference box's centre (origin); points
        // are written at origin + their relative position.
        static void FaceContact(Vector3 origin, Vector3 cI, in Mat3 rR, Vector3 hR, in Mat3 rI, Vector3 hI, int axisR, bool referenceIsB, ContactBuffer output)
        {
            Vector3 axis = Axis(rR, axisR);
            float sign = Vector3.Dot(cI, axis) >= 0 ? 1f : -1f;
            Vector3 n = axis * sign;                      // from the reference box towards the incident one

            // Incident face: the face of I most anti-parallel to n.
            int j = 0;
            float best = -1;
            for (int k = 0; k < 3; k++)
            {
                float c = MathF.Abs(Vector3.Dot(Axis(rI, k), n));
                if (c > best) { best = c; j = k; }
            }
            float incSign = Vector3.Dot(Axis(rI, j), n) > 0 ? -1f : 1f;
            Vector3 incNormal = Axis(rI, j) * incSign;
            Vector3 fc = cI + incNormal * Comp(hI, j);
            Vector3 u = Axis(rI, (j + 1) % 3) * Comp(hI, (j + 1) % 3);
            Vector3 v = Axis(rI, (j + 2) % 3) * Comp(hI, (j + 2) % 3);

            // The buffer's clipping scratch: nothing to zero per call (stackalloc would).
            ClipScratch scratch = output.Clip;
            Vector3[] pts = scratch.Points;
            uint[] keys = scratch.Keys;
            pts[0] = fc + u + v;
            pts[1] = fc - u + v;
            pts[2] = fc - u - v;
            pts[3] = fc + u - v;
            uint[] segs = scratch.Segments;
            for (uint k = 0; k < 4; k++) { keys[(int)k] = k; segs[(int)k] = k; }

            int a1 = (axisR + 1) % 3, a2 = (axisR + 2) % 3;
            Vector3 r1 = Axis(rR, a1), r2 = Axis(rR, a2);
            float e1 = Comp(hR, a1), e2 = Comp(hR, a2);
            Vector3[] planeN = scratch.PlaneNormals;
            float[] planeD = scratch.PlaneOffsets;
            planeN[0] = r1; planeD[0] = e1;
            planeN[1] = -r1; planeD[1] = e1;
            planeN[2] = r2; planeD[2] = e2;
            planeN[3] = -r2; planeD[3] = e2;
            float clipTolerance = 0.001f + 0.002f * MathF.Max(e1, e2);
            int count = PolygonClipper.Clip(pts, keys, segs, 4, planeN, planeD,
                scratch.OtherPoints, scratch.OtherKeys, scratch.OtherSegments, clipTolerance);

            uint refFeature = (uint)((referenceIsB ? 8 : 0) | (axisR * 2 + (sign > 0 ? 0 : 1)));
            uint incFeature = (uint)(j * 2 + (incSign > 0 ? 0 : 1));
            float faceOffset = Comp(hR, axisR);
            output.BeginPatch(referenceIsB ? -n : n);
            for (int k = 0; k < count; k++)
            {
                float sep = Vector3.Dot(pts[k], n) - faceOffset;
                output.Add(origin + (pts[k] - 0.5f * sep * n), sep, (refFeature << 24) | (incFeature << 20) | keys[k]);
            }
        }

        static void EdgeContact(Vector3 cA, in Mat3 rA, Vector3 hA, Vector3 cB, in Mat3 rB, Vector3 hB, int i, int j, ContactBuffer output)
        {
            Vector3 ai = Axis(rA, i), bj = Axis(rB, j);
            Vector3 l = Vector3.Normalize(Vector3.Cross(ai, bj));
            if (Vector3.Dot(l, cB - cA) < 0) l = -l;

            // The edge of A farthest along l and the edge of B farthest along -l.
            // Relative to A's centre, for the precision reason given in Collide.
            Vector3 pA = Vector3.Zero;
            uint signsA = 0;
            for (int k = 0; k < 3; k++)
            {
                if (k == i) continue;
                Vector3 ak = Axis(rA, k);
                bool positive = Vector3.Dot(ak, l) > 0;
                pA += ak * (positive ? Comp(hA, k) : -Comp(hA, k));
                if (positive) signsA |= 1u << k;
            }
            Vector3 pB = cB - cA;
            uint signsB = 0;
            for (int k = 0; k < 3; k++)
            {
                if (k == j) continue;
                Vector3 bk = Axis(rB, k);
                bool positive = Vector3.Dot(bk, l) < 0;
                pB += bk * (positive ? Comp(hB, k) : -Comp(hB, k));
                if (positive) signsB |= 1u << k;
            }
            Vector3 ea = ai * Comp(hA, i), eb = bj * Comp(hB, j);
            SegmentClosestPoints.Compute(pA - ea, pA + ea, pB - eb, pB + eb, out _, out _, out Vector3 qa, out Vector3 qb);
            float sep = Vector3.Dot(qb - qa, l);
            output.BeginPatch(l);
            output.Add(cA + 0.5f * (qa + qb), sep, 0x80000000u | ((uint)i << 12) | (signsA << 8) | ((uint)j << 4) | signsB);
        }

        static Vector3 Axis(in Mat3 r, int i) => i == 0 ? r.C0 : i == 1 ? r.C1 : r.C2;

        static float Comp(Vector3 v, int i) => i == 0 ? v.X : i == 1 ? v.Y : v.Z;

        static float MinComp(Vector3 v) => MathF.Min(v.X, MathF.Min(v.Y, v.Z));
    }
}
