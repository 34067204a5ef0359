using System;
using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum
{
    public sealed partial class World
    {
        ContactEvent[] _events = new ContactEvent[16];
        int _eventCount;
        // End events of contacts lost to RemoveShape/DestroyBody between steps, published first
        // by the next step in the order they happened.
        ContactEvent[] _removalEvents = new ContactEvent[16];
        int _removalEventCount;
        // This step's events before they are put in shape-pair order.
        ContactEvent[] _stepEvents = new ContactEvent[16];
        ulong[] _stepEventKeys = new ulong[16];
        int[] _stepEventOrder = new int[16];
        int _stepEventCount;
        readonly KeyOrder _eventOrder = new KeyOrder();

        /// <summary>
        /// The contact and sensor events of the last step: begin, persist (every step a pair
        /// keeps touching while awake) and end, including the ends caused by removing shapes or
        /// bodies since the step before (those come first). Otherwise ordered by shape pair.
        /// The span stays valid until the next <see cref="Step"/>; it allocates nothing.
        /// Pairs whose bodies all sleep report nothing until they wake.
        /// </summary>
        public ReadOnlySpan<ContactEvent> ContactEvents => new ReadOnlySpan<ContactEvent>(_events, 0, _eventCount);

        // A contact that stopped existing inside the step (its fat boxes parted).
        void RecordStepEnd(int c) => AddStepEvent(c, ContactEventKind.End);

        // A touching contact destroyed by RemoveShape/DestroyBody (its shapes are still live).
        void RecordRemovalEnd(int c)
        {
            if (_removalEventCount == _removalEvents.Length) Array.Resize(ref _removalEvents, 2 * _removalEventCount);
            _removalEvents[_removalEventCount++] = MakeEvent(c, ContactEventKind.End);
        }

        void AddStepEvent(int c, ContactEventKind kind)
        {
            if (_stepEventCount == _stepEvents.Length)
            {
                int n = 2 * _stepEventCount;
                Array.Resize(ref _stepEvents, n);
                Array.Resize(ref _stepEventKeys, n);
                Array.Resize(ref _stepEventOrder, n);
            }
            _stepEvents[_stepEventCount] = MakeEvent(c, kind);
            _stepEventKeys[_stepEventCount] = ContactGraph.Contacts[c].Key;
            _stepEventCount++;
        }

        void AppendEvent(in ContactEvent e)
        {
            if (_eventCount == _events.Length) Array.Resize(ref _events, 2 * _eventCount);
            _events[_eventCount++] = e;
        }

        ContactEvent MakeEvent(int c, ContactEventKind kind)
        {
            ContactGraph g = ContactGraph;
            ref Contact ct = ref g.Contacts[c];
            var e = new ContactEvent
            {
                Kind = kind,
                IsSensor = (ct.Flags & ContactFlags.Sensor) != 0,
                BodyA = new BodyHandle(ct.BodyA, Bodies.Generation[ct.BodyA], Id),
                BodyB = new BodyHandle(ct.BodyB, Bodies.Generation[ct.BodyB], Id),
                ShapeA = new ShapeHandle(ct.ShapeA, Shapes.Generation[ct.ShapeA], Id),
                ShapeB = new ShapeHandle(ct.ShapeB, Shapes.Generation[ct.ShapeB], Id),
            };
            if (kind == ContactEventKind.End || e.IsSensor) return e;
            Vector3 sum = Vector3.Zero;
            for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                if (e.PointCount == 0) e.Normal = mf.Normal;
                for (int i = 0; i < mf.PointCount; i++)
                {
                    ref ContactPoint p = ref ContactManifold.Point(ref mf, i);
                    sum += p.Position;
                    e.NormalImpulse += p.AppliedImpulse;
                    e.PointCount++;
                }
            }
            if (e.PointCount > 0) e.Point = sum / e.PointCount;
            e.RelativeVelocity = ct.RelativeVelocity;
            return e;
        }
    }
}
