using System.Collections.Generic;

namespace Fulcrum
{
    internal sealed partial class ShapeStorage
    {
        /// <summary>
        /// Writes the hulls and meshes once each (shapes share them), then every per-slot array
        /// up to <see cref="SlotStorage.SlotCount"/> and the slot bookkeeping.
        /// </summary>
        public void Save(StateWriter w)
        {
            w.Section("SHAP");
            var data = new List<object>();
            var index = new Dictionary<object, int>();
            int n = SlotCount;
            var dataOf = new int[n];
            for (int i = 0; i < n; i++)
            {
                object? d = Geometry[i].Data;
                if (d == null) { dataOf[i] = -1; continue; }
                if (!index.TryGetValue(d, out int k))
                {
                    k = data.Count;
                    index.Add(d, k);
                    data.Add(d);
                }
                dataOf[i] = k;
            }
            w.Write(data.Count);
            foreach (object d in data)
            {
                if (d is ConvexHull hull) { w.Write((byte)ShapeType.ConvexHull); hull.WriteState(w); }
                else { w.Write((byte)ShapeType.TriangleMesh); ((TriangleMesh)d).WriteState(w); }
            }
            _slots.Save(w);
            for (int i = 0; i < n; i++) Geometry[i].WriteState(w, dataOf[i]);
            var columns = new ColumnWriter(w, n);
            Columns(ref columns);
        }

        /// <summary>Reads what <see cref="Save"/> wrote into a new storage at the saved capacity.</summary>
        public static ShapeStorage Load(StateReader r)
        {
            r.Section("SHAP");
            int count = r.Count("hull and mesh count", 1 << 24);
            var data = new object[count];
            for (int k = 0; k < count; k++)
            {
                var kind = (ShapeType)r.Read<byte>("hull or mesh kind");
                if (kind == ShapeType.ConvexHull) data[k] = ConvexHull.ReadState(r);
                else if (kind == ShapeType.TriangleMesh) data[k] = TriangleMesh.ReadState(r);
                else throw r.Error($"unknown shape data kind {(int)kind}.");
            }
            var s = new ShapeStorage { _slots = SlotAllocator.Load(r, "shapes") };
            int n = s.SlotCount, c = s._slots.Capacity;
            s.Geometry = new ShapeGeometry[c];
            for (int i = 0; i < n; i++) s.Geometry[i] = ShapeGeometry.ReadState(r, data);
            var columns = new ColumnReader(r, n, c);
            s.Columns(ref columns);
            return s;
        }

        // Every per-slot array but the geometry (saved with its shared hulls and meshes) once,
        // in state order: Grow resizes, Save writes and Load reads this list.
        void Columns<TVisitor>(ref TVisitor v) where TVisitor : struct, IColumnVisitor
        {
            v.Column(ref LocalPose, "shape poses");
            v.Column(ref Body, "shape bodies");
            v.Column(ref NextInBody, "shape lists");
            v.Column(ref Density, "shape densities");
            v.Column(ref Friction, "shape friction");
            v.Column(ref Restitution, "shape restitution");
            v.Column(ref FrictionCombine, "shape friction combine modes");
            v.Column(ref RestitutionCombine, "shape restitution combine modes");
            v.Column(ref IsSensor, "shape sensor flags");
            v.Column(ref Layer, "shape layers");
            v.Column(ref CollidesWith, "shape collision masks");
            v.Column(ref UserData, "shape user data");
            v.Column(ref WorldAabb, "shape bounds");
            v.Column(ref ProxyId, "shape proxies");
        }
    }
}
