using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A dynamic bounding-volume hierarchy of fat AABBs (one leaf per proxy). Leaves are
    /// inserted next to the sibling that minimises the surface area heuristic, found by
    /// branch and bound (Bittner, Hapala and Havran, "Fast insertion-based optimization of
    /// bounding volume hierarchies", 2013), and every ancestor on the way back up tries the
    /// four child/grandchild swaps of Kopta et al. ("Fast, effective BVH updates for animated
    /// scenes", I3D 2012), keeping the tree balanced without a global rebuild.
    /// Proxy ids are node indices and stay valid until the proxy is destroyed.
    /// </summary>
    internal sealed partial class DynamicAabbTree
    {
        TreeNode[] _nodes = new TreeNode[16];
        int _root = -1;
        int _free = -1;
        int _nodeCapacityUsed;   // nodes ever handed out (the free list covers the rest)
        int _proxyCount;

        /// <summary>The root node, -1 when empty.</summary>
        public int Root => _root;

        /// <summary>Number of proxies (leaves).</summary>
        public int ProxyCount => _proxyCount;

        /// <summary>Direct read access for traversal and debug drawing.</summary>
        public TreeNode[] Nodes => _nodes;

        /// <summary>Height of the tree (0 for a single leaf, -1 when empty).</summary>
        public int Height => _root < 0 ? -1 : _nodes[_root].Height;

        /// <summary>The fat box of a proxy.</summary>
        public ref readonly Aabb FatAabb(int proxy) => ref _nodes[proxy].Box;

        /// <summary>The user data (shape slot) of a proxy.</summary>
        public int UserData(int proxy) => _nodes[proxy].UserData;

        /// <summary>Sets or clears the moved-this-step mark of a proxy.</summary>
        public void SetMoved(int proxy, bool moved) => _nodes[proxy].Moved = moved;

        /// <summary>Whether the proxy moved this step.</summary>
        public bool WasMoved(int proxy) => _nodes[proxy].Moved;

        /// <summary>Creates a leaf with the given fat box; returns its proxy id.</summary>
        public int CreateProxy(in Aabb fatBox, int userData)
        {
            int leaf = AllocateNode();
            ref TreeNode n = ref _nodes[leaf];
            n.Box = fatBox;
            n.UserData = userData;
            n.Height = 0;
            n.Moved = true;
            InsertLeaf(leaf);
            _proxyCount++;
            return leaf;
        }

        /// <summary>Removes a proxy; its id may be reused.</summary>
        public void DestroyProxy(int proxy)
        {
            RemoveLeaf(proxy);
            FreeNode(proxy);
            _proxyCount--;
        }

        /// <summary>Gives a proxy a new fat box (remove and re-insert; the id is kept).</summary>
        public void MoveProxy(int proxy, in Aabb fatBox)
        {
            RemoveLeaf(proxy);
            _nodes[proxy].Box = fatBox;
            InsertLeaf(proxy);
        }

        /// <summary>Calls <paramref name="callback"/> for every leaf whose box overlaps <paramref name="box"/>.</summary>
        public void Query<T>(in Aabb box, ref T callback) where T : struct, ITreeOverlapCallback
        {
            if (_root < 0) return;
            var stack = new ScratchStack<int>(stackalloc int[64]);
            stack.Push(_root);
            TreeNode[] nodes = _nodes;
            while (!stack.IsEmpty)
            {
                int id = stack.Pop();
                ref readonly TreeNode n = ref nodes[id];
                if (!n.Box.Overlaps(box)) continue;
                if (n.IsLeaf)
                {
                    if (!callback.Visit(id, n.UserData)) break;
                }
                else
                {
                    stack.Push(n.Child1);
                    stack.Push(n.Child2);
                }
            }
            stack.Dispose();
        }

        /// <summary>
        /// Walks the leaves whose boxes the segment origin + t direction, t in [0, maxFraction],
        /// crosses; the callback may shorten the segment (closest hit) or stop it (0).
        /// </summary>
        public void RayCast<T>(Vector3 origin, Vector3 direction, float maxFraction, ref T callback) where T : struct, ITreeRayCallback
        {
            if (_root < 0) return;
            Vector3 inv = RaySlab.Inverse(direction);
            var stack = new ScratchStack<int>(stackalloc int[64]);
            stack.Push(_root);
            TreeNode[] nodes = _nodes;
            while (!stack.IsEmpty && maxFraction > 0)
            {
                int id = stack.Pop();
                ref readonly TreeNode n = ref nodes[id];
                if (!RaySlab.Test(n.Box, origin, inv, maxFraction, out _)) continue;
                if (n.IsLeaf) maxFraction = callback.Visit(id, n.UserData, maxFraction);
                else
                {
                    stack.Push(n.Child1);
                    stack.Push(n.Child2);
                }
            }
            stack.Dispose();
        }

        int AllocateNode()
        {
            if (_free < 0)
            {
                if (_nodeCapacityUsed == _nodes.Length) Array.Resize(ref _nodes, _nodes.Length * 2);
                _nodes[_nodeCapacityUsed].Height = -1;
                _nodes[_nodeCapacityUsed].Parent = _free;
                _free = _nodeCapacityUsed++;
            }
            int id = _free;
            _free = _nodes[id].Parent;
            _nodes[id] = new TreeNode { Parent = -1, Child1 = -1, Child2 = -1, Height = 0, UserData = -1 };
            return id;
        }

        void FreeNode(int id)
        {
            _nodes[id].Height = -1;
            _nodes[id].Parent = _free;
            _free = id;
        }

        void InsertLeaf(int leaf)
        {
            if (_root < 0)
            {
                _root = leaf;
                _nodes[leaf].Parent = -1;
                return;
            }
            Aabb leafBox = _nodes[leaf].Box;
            int sibling = FindBestSibling(leafBox);

            int oldParent = _nodes[sibling].Parent;
            int parent = AllocateNode();
            ref TreeNode p = ref _nodes[parent];
            p.Parent = oldParent;
            p.Box = Aabb.Union(leafBox, _nodes[sibling].Box);
            p.Height = _nodes[sibling].Height + 1;
            p.Child1 = sibling;
            p.Child2 = leaf;
            _nodes[sibling].Parent = parent;
            _nodes[leaf].Parent = parent;
            if (oldParent < 0) _root = parent;
            else if (_nodes[oldParent].Child1 == sibling) _nodes[oldParent].Child1 = parent;
            else _nodes[oldParent].Child2 = parent;

            RefitUpwards(_nodes[leaf].Parent);
        }

        // Branch and bound over the SAH cost of making each node the new leaf's sibling: the
        // cost is the area of the new parent, SA(L u N), plus the growth of every ancestor,
        // which a child inherits; a subtree is skipped when even its best case,
        // SA(L) + inherited growth, cannot beat the best found.
        int FindBestSibling(in Aabb leafBox)
        {
            float leafArea = leafBox.SurfaceArea;
            int best = _root;
            float bestCost = Aabb.Union(leafBox, _nodes[_root].Box).SurfaceArea;
            var stack = new ScratchStack<int>(stackalloc int[64]);
            var inherited = new ScratchStack<float>(stackalloc float[64]);
            stack.Push(_root);
            inherited.Push(0f);
            while (!stack.IsEmpty)
            {
                int id = stack.Pop();
                float inheritedCost = inherited.Pop();
                ref readonly TreeNode n = ref _nodes[id];
                float direct = Aabb.Union(leafBox, n.Box).SurfaceArea;
                float cost = direct + inheritedCost;
                if (cost < bestCost)
                {
                    bestCost = cost;
                    best = id;
                }
                if (n.IsLeaf) continue;
                float childInherited = inheritedCost + direct - n.Box.SurfaceArea;
                if (leafArea + childInherited >= bestCost) continue;
                stack.Push(n.Child1);
                inherited.Push(childInherited);
                stack.Push(n.Child2);
                inherited.Push(childInherited);
            }
            stack.Dispose();
            inherited.Dispose();
            return best;
        }

        void RemoveLeaf(int leaf)
        {
            if (leaf == _root)
            {
                _root = -1;
                return;
            }
            int parent = _nodes[leaf].Parent;
            int grand = _nodes[parent].Parent;
            int sibling = _nodes[parent].Child1 == leaf ? _nodes[parent].Child2 : _nodes[parent].Child1;
            if (grand < 0)
            {
                _root = sibling;
                _nodes[sibling].Parent = -1;
            }
            else
            {
                if (_nodes[grand].Child1 == parent) _nodes[grand].Child1 = sibling;
                else _nodes[grand].Child2 = sibling;
                _nodes[sibling].Parent = grand;
                RefitUpwards(grand);
            }
            FreeNode(parent);
            _nodes[leaf].Parent = -1;
        }

        void RefitUpwards(int index)
        {
            while (index >= 0)
            {
                Rotate(index);
                ref TreeNode n = ref _nodes[index];
                ref readonly TreeNode c1 = ref _nodes[n.Child1];
                ref readonly TreeNode c2 = ref _nodes[n.Child2];
                n.Box = Aabb.Union(c1.Box, c2.Box);
                n.Height = 1 + Math.Max(c1.Height, c2.Height);
                index = n.Parent;
            }
        }

        // Tries swapping a child of A with a grandchild on the other side (B<->F, B<->G,
        // C<->D, C<->E) and keeps the swap that shrinks the changed child's area the most.
        // A's own box is unchanged by any of them, so the cost change is local.
        void Rotate(int a)
        {
            ref TreeNode na = ref _nodes[a];
            int b = na.Child1, c = na.Child2;
            float bestGain = 0;
            int outer = -1, inner = -1;
            bool first = false;
            ConsiderSwaps(b, c, ref bestGain, ref outer, ref inner, ref first);   // B <-> F, B <-> G
            ConsiderSwaps(c, b, ref bestGain, ref outer, ref inner, ref first);   // C <-> D, C <-> E
            if (outer >= 0) SwapIntoSibling(a, outer, inner, first);
        }

        // Swapping "outer" with a child of its sibling "inner" changes only inner's box, which
        // then holds outer and inner's other child: the gain is the area inner loses. Records
        // each of the two swaps that beats the best gain so far (first child, then second).
        void ConsiderSwaps(int outer, int inner, ref float bestGain, ref int bestOuter, ref int bestInner, ref bool bestFirst)
        {
            ref readonly TreeNode ni = ref _nodes[inner];
            if (ni.Height <= 0) return;
            float area = ni.Box.SurfaceArea;
            Aabb moved = _nodes[outer].Box;
            float gainFirst = area - Aabb.Union(moved, _nodes[ni.Child2].Box).SurfaceArea;
            float gainSecond = area - Aabb.Union(moved, _nodes[ni.Child1].Box).SurfaceArea;
            if (gainFirst > bestGain) { bestGain = gainFirst; bestOuter = outer; bestInner = inner; bestFirst = true; }
            if (gainSecond > bestGain) { bestGain = gainSecond; bestOuter = outer; bestInner = inner; bestFirst = false; }
        }

        // Swaps the child "outer" of A with the first (or second) child of A's other child
        // "inner", then refits inner.
        void SwapIntoSibling(int a, int outer, int inner, bool first)
        {
            ref TreeNode ni = ref _nodes[inner];
            int grandchild = first ? ni.Child1 : ni.Child2;
            if (first) ni.Child1 = outer; else ni.Child2 = outer;
            _nodes[outer].Parent = inner;

            ref TreeNode na = ref _nodes[a];
            if (na.Child1 == outer) na.Child1 = grandchild; else na.Child2 = grandchild;
            _nodes[grandchild].Parent = a;

            ref readonly TreeNode i1 = ref _nodes[ni.Child1];
            ref readonly TreeNode i2 = ref _nodes[ni.Child2];
            ni.Box = Aabb.Union(i1.Box, i2.Box);
            ni.Height = 1 + Math.Max(i1.Height, i2.Height);
        }

        /// <summary>
        /// The sum of internal node areas over the root's area: the SAH quality measure (lower
        /// is better). For tests and benchmarks.
        /// </summary>
        public float AreaRatio()
        {
            if (_root < 0) return 0;
            float total = 0;
            for (int i = 0; i < _nodeCapacityUsed; i++)
                if (_nodes[i].Height > 0) total += _nodes[i].Box.SurfaceArea;
            float root = _nodes[_root].Box.SurfaceArea;
            return root > 0 ? total / root : 0;
        }

        /// <summary>
        /// Checks every structural invariant (parent links, heights, boxes contain their
        /// children, leaf count, free list); throws <see cref="InvalidOperationException"/> on
        /// the first broken one. For tests.
        /// </summary>
        public void Validate()
        {
            int leaves = 0;
            if (_root >= 0)
            {
                if (_nodes[_root].Parent != -1) throw new InvalidOperationException("root has a parent");
                leaves = ValidateNode(_root);
            }
            if (leaves != _proxyCount) throw new InvalidOperationException($"leaf count {leaves} != proxy count {_proxyCount}");
            int free = 0;
            for (int f = _free; f >= 0; f = _nodes[f].Parent)
            {
                if (_nodes[f].Height != -1) throw new InvalidOperationException($"free node {f} is in use");
                if (++free > _nodeCapacityUsed) throw new InvalidOperationException("free list loops");
            }
            int used = _proxyCount == 0 ? 0 : 2 * _proxyCount - 1;
            if (used + free != _nodeCapacityUsed) throw new InvalidOperationException($"nodes leaked: {used} used + {free} free != {_nodeCapacityUsed}");
        }

        int ValidateNode(int id)
        {
            ref readonly TreeNode n = ref _nodes[id];
            if (n.IsLeaf)
            {
                if (n.Height != 0) throw new InvalidOperationException($"leaf {id} has height {n.Height}");
                return 1;
            }
            ref readonly TreeNode c1 = ref _nodes[n.Child1];
            ref readonly TreeNode c2 = ref _nodes[n.Child2];
            if (c1.Parent != id || c2.Parent != id) throw new InvalidOperationException($"children of {id} do not point back");
            if (n.Height != 1 + Math.Max(c1.Height, c2.Height)) throw new InvalidOperationException($"node {id} height is stale");
            if (!n.Box.Contains(c1.Box) || !n.Box.Contains(c2.Box)) throw new InvalidOperationException($"node {id} box does not contain its children");
            return ValidateNode(n.Child1) + ValidateNode(n.Child2);
        }
    }
}
