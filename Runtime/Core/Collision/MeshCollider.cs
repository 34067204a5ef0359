using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A convex shape (A) against a static triangle mesh (B), in the mesh frame. The mesh's
    /// BVH yields the triangles near the shape; each is a one-sided convex polygon:
    /// separated cores go through GJK and face clipping like any convex pair (ignoring
    /// triangles the shape is behind), overlapping cores are pushed out along the triangle's
    /// normal, which keeps a shape resting across triangle edges from catching on them.
    /// The per-triangle patches are then grouped by normal into at most
    /// <see cref="ContactGraph.MaxManifoldsPerPair"/> patches (deepest first), so a box in the
    /// corner of a mesh room gets one manifold per wall. Feature ids mix in the triangle index.
    /// </summary>
    internal static class MeshCollider
    {
        /// <summary>Cosine above which two triangle patches share a manifold (about 1.8 degrees).</summary>
        const float SameNormalCosine = 0.9995f;

        struct TriangleVisitor : ITreeOverlapCallback
        {
            public SupportShape Convex;
            public TriangleMesh Mesh;
            public ContactBuffer Output;

            public Aabb Bounds;

            public bool Visit(int proxyId, int triangle)
            {
                if (!Mesh.TriangleOverlaps(Bounds, triangle, out _, out _, out _)) return true;
                int before = Output.PointCount;
                TriangleContact(Convex, Mesh, triangle, Output);
                uint salt = (uint)triangle * 0x9E3779B1u;
                for (int i = before; i < Output.PointCount; i++) Output.Id[i] = (Output.Id[i] ^ salt) * 0x85EBCA77u + (uint)triangle;
                return true;
            }
        }

        /// <summary>Pair function: A is convex, B a triangle mesh.</summary>
        public static void Collide(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output)
        {
            var mesh = (TriangleMesh)b.Data!;
            Pose local = poseB.Inverse() * poseA;
            ContactBuffer scratch = output.Scratch;
            scratch.Clear(output.Speculative);
            var visitor = new TriangleVisitor { Convex = SupportShape.From(a, local), Mesh = mesh, Output = scratch };
            visitor.Bounds = visitor.Convex.Bounds().Expanded(output.Speculative);
            mesh.Bvh.Query(visitor.Bounds, ref visitor);
            Merge(scratch, poseB, output);
        }

        /// <summary>One triangle (mesh frame) against a convex core in the same frame.</summary>
        internal static void TriangleContact(in SupportShape convex, TriangleMesh mesh, int t, ContactBuffer output)
        {
            mesh.GetTriangle(t, out Vector3 a, out Vector3 b, out Vector3 c);
            Vector3 nT = mesh.Normals[t];
            float plane = Vector3.Dot(nT, a);
            float r = convex.Radius;
            // Wholly behind the (one-sided) triangle: nothing.
            if (Vector3.Dot(nT, convex.Support(nT, out _)) + r < plane) return;
            var tri = SupportShape.Triangle(a, b, c);
            float dist = Gjk.Distance(convex, tri, out Vector3 pa, out Vector3 pb, out _);
            if (dist > CollisionMargins.CoreTolerance)
            {
                if (dist - r > output.Speculative) return;
                Vector3 n = (pb - pa) / dist;
                if (Vector3.Dot(n, nT) <= 0)
                {
                    ConvexCollider.Manifold(convex, tri, n, dist, pa, output);
                    return;
                }
                // The core is behind the plane: sunk straight under the face (push it out the
                // front), or behind and beside it (another triangle's business).
                if (Vector3.Dot(n, nT) < 0.99f) return;
            }
            Vector3 deepest = convex.Support(-nT, out _);
            float coreSeparation = Vector3.Dot(nT, deepest) - plane;
            if (coreSeparation - r > output.Speculative) return;
            ConvexCollider.Manifold(convex, tri, -nT, coreSeparation, deepest, output);
        }

        static bool IsDuplicate(ContactBuffer output, Vector3 x)
        {
            int start = output.PatchStart[output.PatchCount - 1];
            for (int i = start; i < output.PointCount; i++)
                if (Vector3.DistanceSquared(output.Position[i], x) < 1e-8f) return true;
            return false;
        }

        // Groups the scratch patches (mesh frame) by normal, deepest first, and writes them
        // to the output in world space.
        static void Merge(ContactBuffer scratch, in Pose meshPose, ContactBuffer output)
        {
            int patches = scratch.PatchCount;
            if (scratch.PointCount == 0) return;
            const int MaxGroups = ContactGraph.MaxManifoldsPerPair;
            Span<int> group = stackalloc int[patches];
            Span<float> depth = stackalloc float[patches];
            Span<int> order = stackalloc int[patches];
            Span<Vector3> groupNormal = stackalloc Vector3[MaxGroups];
            for (int p = 0; p < patches; p++)
            {
                float d = float.MaxValue;
                for (int i = scratch.PatchStart[p]; i < scratch.PatchStart[p + 1]; i++) d = MathF.Min(d, scratch.Separation[i]);
                depth[p] = d;
                order[p] = p;
            }
            for (int i = 1; i < patches; i++)
                for (int j = i; j > 0 && (depth[order[j]] < depth[order[j - 1]] || (depth[order[j]] == depth[order[j - 1]] && order[j] < order[j - 1])); j--)
                    (order[j], order[j - 1]) = (order[j - 1], order[j]);

            int groups = 0;
            for (int k = 0; k < patches; k++)
            {
                int p = order[k];
                group[p] = -1;
                if (scratch.PatchStart[p + 1] == scratch.PatchStart[p]) continue;
                Vector3 n = scratch.PatchNormal[p];
                int best = -1;
                float bestDot = -2;
                for (int g = 0; g < groups; g++)
                {
                    float dot = Vector3.Dot(n, groupNormal[g]);
                    if (dot > bestDot) { bestDot = dot; best = g; }
                }
                if (best >= 0 && (bestDot >= SameNormalCosine || groups == MaxGroups)) group[p] = best;
                else
                {
                    groupNormal[groups] = n;
                    group[p] = groups++;
                }
            }
            for (int g = 0; g < groups; g++)
            {
                output.BeginPatch(meshPose.TransformDirection(groupNormal[g]));
                for (int k = 0; k < patches; k++)
                {
                    int p = order[k];
                    if (group[p] != g) continue;
                    for (int i = scratch.PatchStart[p]; i < scratch.PatchStart[p + 1]; i++)
                    {
                        Vector3 x = meshPose.TransformPoint(scratch.Position[i]);
                        // Triangles sharing an edge or vertex report the same point: keep one.
                        if (!IsDuplicate(output, x)) output.Add(x, scratch.Separation[i], scratch.Id[i]);
                    }
                }
            }
        }
    }
}
