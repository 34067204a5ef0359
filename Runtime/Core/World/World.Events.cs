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

        // Copies the solver's impulses back to the persistent contacts, then turns each awake
        // contact's touching state (and each sensor's overlap) into begin/persist/end events.
        void PublishEvents()
        {
            _queryBoundsStale = true;
            _eventCount = 0;
            for (int i = 0; i < _removalEventCount; i++) AppendEvent(_removalEvents[i]);
            _removalEventCount = 0;

            ContactGraph g = ContactGraph;
            float slop = _settings.LinearSlop;
            for (int k = 0; k < g.DenseCount; k++)
            {
                int c = g.Dense[k];
                ref Contact ct = ref g.Contacts[c];
                if ((ct.Flags & ContactFlags.Updated) == 0) continue;
                bool was = (ct.Flags & ContactFlags.Touching) != 0;
                bool now = (ct.Flags & ContactFlags.Sensor) != 0
                    ? (ct.Flags & ContactFlags.Overlapping) != 0
                    : IsTouching(ref ct, slop);
                if (now) ct.Flags |= ContactFlags.Touching;
                else ct.Flags &= ~ContactFlags.Touching;
                if (now) AddStepEvent(c, was ? ContactEventKind.Persist : ContactEventKind.Begin);
                else if (was) AddStepEvent(c, ContactEventKind.End);
            }

            int n = _stepEventCount;
            for (int i = 0; i < n; i++) _stepEventOrder[i] = i;
            _eventOrder.Sort(_stepEventKeys, _stepEventOrder, n);
            for (int i = 0; i < n; i++) AppendEvent(_stepEvents[_stepEventOrder[i]]);
            _stepEventCount = 0;
        }

        // Touching: a point within the linear slop, or one the solver pushed on (a
        // speculative point that stopped a fast body counts as a hit).
        bool IsTouching(ref Contact ct, float slop)
        {
            ContactGraph g = ContactGraph;
            for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                for (int i = 0; i < mf.PointCount; i++)
                {
                    ref ContactPoint p = ref ContactManifold.Point(ref mf, i);
                    if (p.Separation <= slop || p.NormalImpulse > 0) return true;
                }
            }
            return false;
        }

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
