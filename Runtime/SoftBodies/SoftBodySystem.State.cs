using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    public sealed partial class SoftBodySystem : IStateStage
    {
        static readonly Type[] StateTypes =
        {
            typeof(Vector2), typeof(TetElement), typeof(TetGradients), typeof(TriangleElement), typeof(BendElement),
            typeof(Attachment), typeof(SoftPlasticity), typeof(SoftSolver),
        };

        bool IStateStage.HasState => _slots.SlotCount > 0;

        Type[] IStateStage.LayoutTypes => StateTypes;

        // The slots (live or not, with generations), the order bodies step in, each live body's
        // state, the divergence record and the count of steps taken again.
        void IStateStage.SaveState(StateWriter w)
        {
            w.Write(_slots.SlotCount);
            for (int i = 0; i < _slots.SlotCount; i++)
            {
                w.Write(_slots.Generation[i]);
                w.Write(_bodies[i] != null);
            }
            w.Write(Count);
            for (int k = 0; k < Count; k++) w.Write(_slots.Active[k]);
            for (int k = 0; k < Count; k++) this[k].WriteState(w);
            w.Write(DivergenceCount);
            w.Write(LastDiverged.Index);
            w.Write(LastDiverged.Generation);
            w.Write(LastDivergedStep);
            w.Write(RetriedSteps);
            w.Write(_divergedLastStep);
            w.Write(_retrySubstepFactor);
        }

        Action IStateStage.PrepareRestore(StateReader r)
        {
            int slots = r.Read<int>("soft body slot count");
            if (slots != _slots.SlotCount)
                throw r.Error($"the state has {slots} soft body slots, this world {_slots.SlotCount}: build the same soft bodies before restoring.");
            for (int i = 0; i < slots; i++)
            {
                int generation = r.Read<int>("soft body generation");
                bool live = r.Read<bool>("soft body liveness");
                if (generation != _slots.Generation[i] || live != (_bodies[i] != null))
                    throw r.Error($"soft body slot {i} is {(live ? "live" : "free")} at generation {generation} in the state and {(_bodies[i] != null ? "live" : "free")} at {_slots.Generation[i]} here: build the same soft bodies before restoring.");
            }
            int count = r.Count("live soft body count", slots);
            if (count != Count) throw r.Error($"the state has {count} live soft bodies, this world {Count}.");
            var order = new SoftBody[count];
            var orderSlots = new int[count];
            for (int k = 0; k < count; k++)
            {
                int slot = r.Read<int>("soft body slot");
                if ((uint)slot >= (uint)slots || !(_bodies[slot] is SoftBody body) || Array.IndexOf(order, body) >= 0)
                    throw r.Error($"live soft body {k} names slot {slot}, which is not live here or is named twice.");
                order[k] = body;
                orderSlots[k] = slot;
            }
            var commits = new Action[count];
            for (int k = 0; k < count; k++) commits[k] = order[k].PrepareRestore(r);
            int divergences = r.Read<int>("soft divergence count");
            var last = new SoftBodyHandle(r.Read<int>("soft divergence slot"), r.Read<int>("soft divergence generation"), _world.Id);
            long lastStep = r.Read<long>("soft divergence step");
            int retried = r.Read<int>("soft retried step count");
            bool divergedLast = r.Read<bool>("soft divergence in the last step");
            int retryFactor = r.Read<int>("soft retry substep factor");
            if (retryFactor < 1 || retryFactor > 64) throw r.Error($"soft retry substep factor {retryFactor} is not 1 to 64.");
            return () =>
            {
                _slots.SetActiveOrder(orderSlots);
                foreach (Action commit in commits) commit();
                DivergenceCount = divergences;
                LastDiverged = last;
                LastDivergedStep = lastStep;
                RetriedSteps = retried;
                _divergedLastStep = divergedLast;
                _retrySubstepFactor = retryFactor;
            };
        }
    }
}
