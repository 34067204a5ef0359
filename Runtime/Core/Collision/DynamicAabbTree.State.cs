namespace Fulcrum.Collision
{
    internal sealed partial class DynamicAabbTree
    {
        /// <summary>Writes the nodes as they are (structure, free list, moved flags): queries after a restore visit them in the same order.</summary>
        public void Save(StateWriter w)
        {
            w.Write(_root);
            w.Write(_free);
            w.Write(_proxyCount);
            w.WritePool(_nodes, _nodeCapacityUsed);
        }

        /// <summary>Replaces this (new, empty) tree with what <see cref="Save"/> wrote, checking every link.</summary>
        public void Load(StateReader r, string what)
        {
            int root = r.Read<int>(what + " root"), free = r.Read<int>(what + " free list");
            int proxies = r.Read<int>(what + " proxy count");
            TreeNode[] nodes = r.ReadPool<TreeNode>(what + " nodes", out int n);
            if (nodes.Length == 0 || root < -1 || root >= n || free < -1 || free >= n || proxies < 0 || proxies > n)
                throw r.Error($"{what}: root {root}, free list {free} or {proxies} proxies out of range for {n} nodes.");
            for (int i = 0; i < n; i++)
            {
                ref TreeNode t = ref nodes[i];
                if (t.Parent < -1 || t.Parent >= n || t.Child1 < -1 || t.Child1 >= n || t.Child2 < -1 || t.Child2 >= n)
                    throw r.Error($"{what}: node {i} links outside the tree.");
            }
            _nodes = nodes;
            _root = root;
            _free = free;
            _proxyCount = proxies;
            _nodeCapacityUsed = n;
        }
    }
}
