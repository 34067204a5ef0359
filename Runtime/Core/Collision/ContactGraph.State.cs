namespace Fulcrum.Collision
{
    internal sealed partial class ContactGraph
    {
        /// <summary>
        /// Writes the contacts (with their touching flags and reuse poses), the manifolds with
        /// their accumulated impulses and reuse points, the pair map, the per-shape lists and the
        /// free lists: everything the next narrow phase and warm start read.
        /// </summary>
        public void Save(StateWriter w)
        {
            w.Section("CONT");
            w.Write(_contactFree);
            w.WritePool(Contacts, _contactsUsed);
            w.WritePool(Dense, DenseCount);
            w.WritePool(_edgeNext, 2 * _contactsUsed);
            w.WritePool(_edgePrev, 2 * _contactsUsed);
            w.WriteArray(_shapeHead);
            _map.Save(w);
            w.Write(_manifoldFree);
            w.WritePool(Manifolds, _manifoldsUsed);
            w.WritePool(ManifoldNext, _manifoldsUsed);
            w.WritePool(LocalNormal, _manifoldsUsed);
            w.WritePool(LocalPointA, 4 * _manifoldsUsed);
            w.WritePool(LocalPointB, 4 * _manifoldsUsed);
            w.WritePool(SeparationOffset, 4 * _manifoldsUsed);
        }

        /// <summary>Reads what <see cref="Save"/> wrote into a new graph, checking its links.</summary>
        public static ContactGraph Load(StateReader r)
        {
            r.Section("CONT");
            var g = new ContactGraph();
            g._contactFree = r.Read<int>("contact free list");
            g.Contacts = r.ReadPool<Contact>("contacts", out g._contactsUsed);
            g.Dense = r.ReadPool<int>("live contacts", out g.DenseCount);
            g._edgeNext = r.ReadPool<int>("contact edges", out int edges);
            g._edgePrev = r.ReadPool<int>("contact edges", out int edges2);
            g._shapeHead = r.ReadArray<int>("shape contact lists");
            g._map = PairMap.Load(r, g._contactsUsed);
            g._manifoldFree = r.Read<int>("manifold free list");
            g.Manifolds = r.ReadPool<ContactManifold>("manifolds", out g._manifoldsUsed);
            g.ManifoldNext = r.ReadPool<int>("manifold links", out int links);
            g.LocalNormal = r.ReadPool<System.Numerics.Vector3>("manifold normals", out int normals);
            g.LocalPointA = r.ReadPool<System.Numerics.Vector3>("manifold points on A", out int pointsA);
            g.LocalPointB = r.ReadPool<System.Numerics.Vector3>("manifold points on B", out int pointsB);
            g.SeparationOffset = r.ReadPool<float>("manifold separations", out int offsets);
            int c = g._contactsUsed, m = g._manifoldsUsed;
            if (g.Dense.Length != g.Contacts.Length || g._edgeNext.Length != 2 * g.Contacts.Length || g._edgePrev.Length != 2 * g.Contacts.Length
                || edges != 2 * c || edges2 != 2 * c || g.DenseCount > c || g._map.Count != g.DenseCount)
                throw r.Error("the contact pools do not match each other.");
            if (g.ManifoldNext.Length != g.Manifolds.Length || g.LocalNormal.Length != g.Manifolds.Length || g.LocalPointA.Length != 4 * g.Manifolds.Length
                || g.LocalPointB.Length != 4 * g.Manifolds.Length || g.SeparationOffset.Length != 4 * g.Manifolds.Length
                || links != m || normals != m || pointsA != 4 * m || pointsB != 4 * m || offsets != 4 * m)
                throw r.Error("the manifold pools do not match each other.");
            if (g._contactFree < -1 || g._contactFree >= c || g._manifoldFree < -1 || g._manifoldFree >= m)
                throw r.Error("a free list starts outside its pool.");
            for (int k = 0; k < g.DenseCount; k++)
            {
                int id = g.Dense[k];
                if ((uint)id >= (uint)c || g.Contacts[id].DenseIndex != k) throw r.Error($"live contact {k} ({id}) does not match its record.");
                int first = g.Contacts[id].FirstManifold;
                if (first < -1 || first >= m) throw r.Error($"contact {id} starts its manifolds at {first} of {m}.");
            }
            for (int i = 0; i < m; i++)
                if (g.ManifoldNext[i] < -1 || g.ManifoldNext[i] >= m) throw r.Error($"manifold {i} links to {g.ManifoldNext[i]} of {m}.");
            for (int e = 0; e < 2 * c; e++)
                if (g._edgeNext[e] < -1 || g._edgeNext[e] >= 2 * c || g._edgePrev[e] < -1 || g._edgePrev[e] >= 2 * c)
                    throw r.Error($"contact edge {e} links outside the pool.");
            foreach (int e in g._shapeHead)
                if (e < -1 || e >= 2 * c) throw r.Error($"a shape's contact list starts at edge {e} of {2 * c}.");
            return g;
        }
    }
}
