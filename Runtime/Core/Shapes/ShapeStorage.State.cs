using System.Collections.Generic;
using Fulcrum.Mathematics;

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
            w.WriteArray(LocalPose, n);
            w.WriteArray(Body, n);
            w.WriteArray(NextInBody, n);
            w.WriteArray(Density, n);
            w.WriteArray(Friction, n);
            w.WriteArray(Restitution, n);
            w.WriteArray(FrictionCombine, n);
            w.WriteArray(RestitutionCombine, n);
            w.WriteArray(IsSensor, n);
            w.WriteArray(Layer, n);
            w.WriteArray(CollidesWith, n);
            w.WriteArray(UserData, n);
            w.WriteArray(WorldAabb, n);
            w.WriteArray(ProxyId, n);
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
            s.LocalPose = r.ReadSlots<Pose>("shape poses", n, c);
            s.Body = r.ReadSlots<int>("shape bodies", n, c);
            s.NextInBody = r.ReadSlots<int>("shape lists", n, c);
            s.Density = r.ReadSlots<float>("shape densities", n, c);
            s.Friction = r.ReadSlots<float>("shape friction", n, c);
            s.Restitution = r.ReadSlots<float>("shape restitution", n, c);
            s.FrictionCombine = r.ReadSlots<CombineMode>("shape friction combine modes", n, c);
            s.RestitutionCombine = r.ReadSlots<CombineMode>("shape restitution combine modes", n, c);
            s.IsSensor = r.ReadSlots<bool>("shape sensor flags", n, c);
            s.Layer = r.ReadSlots<int>("shape layers", n, c);
            s.CollidesWith = r.ReadSlots<uint>("shape collision masks", n, c);
            s.UserData = r.ReadSlots<ulong>("shape user data", n, c);
            s.WorldAabb = r.ReadSlots<Aabb>("shape bounds", n, c);
            s.ProxyId = r.ReadSlots<int>("shape proxies", n, c);
            return s;
        }
    }
}
