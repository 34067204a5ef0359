using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A static bounding-volume hierarchy over a mesh's triangles, built once top-down: each
    /// node splits its triangles at the best of 12 bins per axis by the surface area heuristic
    /// (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007), leaves
    /// of up to 4 triangles, nodes in depth-first order so the left child follows its parent.
    /// </summary>
    internal sealed class TriangleBvh
    {
        const int LeafSize = 4;
        const int Bins = 12;

        public readonly BvhNode[] Nodes;
        /// <summary>Triangle indices in leaf order.</summary>
        public readonly int[] Triangles;
        public readonly int Depth;

        public TriangleBvh(Vector3[] vertices, int[] indices)
        {
            int n = indices.Length / 3;
            var boxes = new Aabb[n];
            var centers = new Vector3[n];
            for (int t = 0; t < n; t++)
            {
                Vector3 a = vertices[indices[3 * t]], b = vertices[indices[3 * t + 1]], c = vertices[indices[3 * t + 2]];
                boxes[t] = Aabb.OfTriangle(a, b, c);
                centers[t] = (a + b + c) / 3f;
            }
            Triangles = new int[n];
            for (int t = 0; t < n; t++) Triangles[t] = t;
            var nodes = new System.Collections.Generic.List<BvhNode>(2 * n / LeafSize + 1);
            Depth = Build(nodes, boxes, centers, 0, n, 1);
            Nodes = nodes.ToArray();
        }

        int Build(System.Collections.Generic.List<BvhNode> nodes, Aabb[] boxes, Vector3[] centers, int start, int count, int depth)
        {
            int index = nodes.Count;
            Aabb box = Aabb.Empty, centroidBox = Aabb.Empty;
            for (int i = start; i < start + count; i++)
            {
                box = Aabb.Union(box, boxes[Triangles[i]]);
                centroidBox = Aabb.Union(centroidBox, centers[Triangles[i]]);
            }
            nodes.Add(new BvhNode { Box = box, Start = start, Count = count });
            if (count <= LeafSize) return depth;

            int split = FindSplit(boxes, centers, start, count, centroidBox, out int axis, out float position);
            if (split < 0)
            {
                // All centroids in one bin (or coincide): split the list in half.
                split = start + count / 2;
            }
            else
            {
                int lo = start, hi = start + count - 1;
                while (lo <= hi)
                {
                    if (Comp(centers[Triangles[lo]], axis) < position) lo++;
                    else { (Triangles[lo], Triangles[hi]) = (Triangles[hi], Triangles[lo]); hi--; }
                }
                split = lo;
                if (split == start || split == start + count) split = start + count / 2;
            }
            int leftDepth = Build(nodes, boxes, centers, start, split - start, depth + 1);
            int right = nodes.Count;
            int rightDepth = Build(nodes, boxes, centers, split, start + count - split, depth + 1);
            nodes[index] = new BvhNode { Box = box, Start = right, Count = 0 };
            return Math.Max(leftDepth, rightDepth);
        }

        int FindSplit(Aabb[] boxes, Vector3[] centers, int start, int count, in Aabb centroidBox, out int bestAxis, out float bestPosition)
        {
            bestAxis = 0;
            bestPosition = 0;
            float bestCost = float.MaxValue;
            int found = -1;
            Span<int> binCount = stackalloc int[Bins];
            var binBox = new Aabb[Bins];
            for (int axis = 0; axis < 3; axis++)
            {
                float lo = Comp(centroidBox.Min, axis), hi = Comp(centroidBox.Max, axis);
                if (!(hi - lo > 1e-9f)) continue;
                float scale = Bins / (hi - lo);
                binCount.Clear();
                for (int b = 0; b < Bins; b++) binBox[b] = Aabb.Empty;
                for (int i = start; i < start + count; i++)
                {
                    int t = Triangles[i];
                    int b = Math.Min(Bins - 1, (int)((Comp(centers[t], axis) - lo) * scale));
                    binCount[b]++;
                    binBox[b] = Aabb.Union(binBox[b], boxes[t]);
                }
                for (int s = 1; s < Bins; s++)
                {
                    Aabb left = Aabb.Empty, right = Aabb.Empty;
                    int nl = 0, nr = 0;
                    for (int b = 0; b < s; b++) if (binCount[b] > 0) { left = Aabb.Union(left, binBox[b]); nl += binCount[b]; }
                    for (int b = s; b < Bins; b++) if (binCount[b] > 0) { right = Aabb.Union(right, binBox[b]); nr += binCount[b]; }
                    if (nl == 0 || nr == 0) continue;
                    float cost = nl * left.SurfaceArea + nr * right.SurfaceArea;
                    if (cost < bestCost)
                    {
                        bestCost = cost;
                        bestAxis = axis;
                        bestPosition = lo + s / scale;
                        found = s;
                    }
                }
            }
            return found;
        }

        static float Comp(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;

        /// <summary>Calls the callback for every triangle whose node boxes overlap <paramref name="box"/> (mesh frame).</summary>
        public void Query<T>(in Aabb box, ref T callback) where T : struct, ITreeOverlapCallback
        {
            var stack = new ScratchStack<int>(stackalloc int[64]);
            stack.Push(0);
            while (!stack.IsEmpty)
            {
                int i = stack.Pop();
                ref readonly BvhNode n = ref Nodes[i];
                if (!n.Box.Overlaps(box)) continue;
                if (n.Count > 0)
                {
                    bool go = true;
                    for (int k = n.Start; k < n.Start + n.Count && go; k++) go = callback.Visit(k, Triangles[k]);
                    if (!go) break;
                }
                else
                {
                    stack.Push(n.Start);
                    stack.Push(i + 1);
                }
            }
            stack.Dispose();
        }

        /// <summary>Walks the triangles whose node boxes the segment origin + t d, t in [0, max], crosses.</summary>
        public void RayCast<T>(Vector3 origin, Vector3 direction, float maxFraction, ref T callback) where T : struct, ITreeRayCallback
        {
            Vector3 inv = RaySlab.Inverse(direction);
            var stack = new ScratchStack<int>(stackalloc int[64]);
            stack.Push(0);
            while (!stack.IsEmpty && maxFraction > 0)
            {
                int i = stack.Pop();
                ref readonly BvhNode n = ref Nodes[i];
                if (!RaySlab.Test(n.Box, origin, inv, maxFraction, out _)) continue;
                if (n.Count > 0)
                {
                    for (int k = n.Start; k < n.Start + n.Count && maxFraction > 0; k++)
                        maxFraction = callback.Visit(k, Triangles[k], maxFraction);
                }
                else
                {
                    stack.Push(n.Start);
                    stack.Push(i + 1);
                }
            }
            stack.Dispose();
        }
    }
}
