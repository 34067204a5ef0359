namespace Fulcrum.Dynamics
{
    internal sealed partial class JointStorage
    {
        /// <summary>Writes every joint (definition, accumulated impulses, reports), the names, the per-body joint lists and the slot bookkeeping.</summary>
        public void Save(StateWriter w)
        {
            w.Section("JOIN");
            _slots.Save(w);
            int n = SlotCount;
            w.WriteArray(Data, n);
            w.WriteStrings(Name, n);
            w.WriteArray(NextEdge, 2 * n);
            w.WriteArray(FirstEdge);
        }

        /// <summary>Reads what <see cref="Save"/> wrote into a new storage, checking body and edge indices against <paramref name="bodySlots"/>.</summary>
        public static JointStorage Load(StateReader r, int bodySlots)
        {
            r.Section("JOIN");
            var j = new JointStorage { _slots = SlotAllocator.Load(r, "joints") };
            int n = j.SlotCount, c = j._slots.Capacity;
            j.Data = r.ReadSlots<JointData>("joints", n, c);
            j.Name = r.ReadStringSlots("joint names", n, c);
            j.NextEdge = r.ReadSlots<int>("joint list links", 2 * n, 2 * c);
            j.FirstEdge = r.ReadArray<int>("joint list heads");
            for (int k = 0; k < j.ActiveCount; k++)
            {
                ref JointData d = ref j.Data[j.Active[k]];
                if (d.BodyA >= bodySlots || d.BodyB >= bodySlots || d.BodyA < -1 || d.BodyB < -1)
                    throw r.Error($"joint {j.Active[k]} names body slots {d.BodyA} and {d.BodyB}; the state has {bodySlots}.");
            }
            for (int e = 0; e < 2 * n; e++)
                if (j.NextEdge[e] >= 2 * n) throw r.Error($"joint list link {e} points to {j.NextEdge[e]}.");
            foreach (int e in j.FirstEdge)
                if (e >= 2 * n) throw r.Error($"a joint list head points to {e}.");
            return j;
        }
    }
}
