using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Components
{
    public sealed partial class PhysicsScene
    {
        readonly HandleOwners<Collider> _colliderOwners = new HandleOwners<Collider>();
        ContactEvent[] _events = new ContactEvent[64];
        int _eventCount;
        ContactEvent[] _injected = new ContactEvent[16];
        int _injectedCount;
        readonly Collision _collision = new Collision();
        string? _dispatching;

        /// <summary>True while collision, trigger or joint-break messages are being sent.</summary>
        public bool isDispatchingMessages => _dispatching != null;

        /// <summary>
        /// The collider that owns <paramref name="shape"/>, or null. A shape removed since the
        /// last step still finds its (destroyed or disabled) collider, so end events can name it.
        /// </summary>
        public Collider? GetCollider(ShapeHandle shape) => _colliderOwners.Get(shape.Id);

        internal void MapShape(ShapeHandle shape, Collider c) => _colliderOwners.Set(shape.Id, c);

        // The entry stays until the slot is reused: end events for the shape still resolve.
        internal void UnmapShape(ShapeHandle shape) { }

        /// <summary>
        /// Queues a contact event to be dispatched after the next step together with the
        /// world's own (tests use it to drive dispatch without a narrow phase).
        /// </summary>
        internal void InjectContactEvent(in ContactEvent e)
        {
            if (_injectedCount == _injected.Length) Array.Resize(ref _injected, _injected.Length * 2);
            _injected[_injectedCount++] = e;
        }

        // Copies this step's events out of the world first: messages may add or remove shapes,
        // which may touch the world's buffers.
        void DispatchMessages()
        {
            _eventCount = 0;
            ReadOnlySpan<ContactEvent> world = WorldEvents.Of(_world);
            for (int k = 0; k < world.Length; k++) AppendEvent(world[k]);
            for (int k = 0; k < _injectedCount; k++) AppendEvent(_injected[k]);
            _injectedCount = 0;
            if (_eventCount == 0) return;
            try
            {
                // Unity's order within a step: trigger messages, then collision messages.
                for (int k = 0; k < _eventCount; k++)
                    if (_events[k].IsSensor) DispatchTrigger(_events[k]);
                for (int k = 0; k < _eventCount; k++)
                    if (!_events[k].IsSensor) DispatchCollision(_events[k]);
            }
            finally
            {
                _dispatching = null;
            }
        }

        void AppendEvent(in ContactEvent e)
        {
            if (_eventCount == _events.Length) Array.Resize(ref _events, _events.Length * 2);
            _events[_eventCount++] = e;
        }

        void DispatchTrigger(in ContactEvent e)
        {
            Collider? a = GetCollider(e.ShapeA), b = GetCollider(e.ShapeB);
            if (a == null || b == null) return;
            SendTrigger(a, b, e.Kind);
            SendTrigger(b, a, e.Kind);
        }

        void DispatchCollision(in ContactEvent e)
        {
            Collider? a = GetCollider(e.ShapeA), b = GetCollider(e.ShapeB);
            if (a == null || b == null) return;
            // Seen from A the normal points from B to A (-n); A received -n * impulse.
            SendCollision(a, b, e, -e.Normal, e.RelativeVelocity);
            SendCollision(b, a, e, e.Normal, -e.RelativeVelocity);
        }

        void SendTrigger(Collider self, Collider other, ContactEventKind kind)
        {
            if (!Receives(self)) return;
            _dispatching = kind == ContactEventKind.Begin ? "OnTriggerEnter" : kind == ContactEventKind.Persist ? "OnTriggerStay" : "OnTriggerExit";
            Send(self, other, kind, null);
        }

        void SendCollision(Collider self, Collider other, in ContactEvent e, Vector3 normalTowardsSelf, Vector3 relativeVelocity)
        {
            if (!Receives(self)) return;
            _dispatching = e.Kind == ContactEventKind.Begin ? "OnCollisionEnter" : e.Kind == ContactEventKind.Persist ? "OnCollisionStay" : "OnCollisionExit";
            Vector3 impulse = normalTowardsSelf * e.NormalImpulse;
            Collision c = _collision;
            c.Reset(self, other, impulse, relativeVelocity);
            if (e.Kind != ContactEventKind.End && !AddManifoldPoints(c, e, self, other, self == GetCollider(e.ShapeA)) && e.PointCount > 0)
            {
                // No live contact for the pair (an injected event): the event's average point stands in.
                c.AddContact(new ContactPoint
                {
                    point = e.Point,
                    normal = normalTowardsSelf,
                    separation = 0f,
                    impulse = impulse,
                    thisCollider = self,
                    otherCollider = other,
                });
            }
            Send(self, other, e.Kind, c);
        }

        // One contact message (a collision with c, a trigger without) to the behaviours on self's
        // entity, then on its rigidbody's entity when that is another one: a child collider's
        // messages reach the body's scripts too, as in Unity.
        static void Send(Collider self, Collider other, ContactEventKind kind, Collision? c)
        {
            Entity e = self.entity;
            SendTo(e, other, kind, c);
            Rigidbody? rb = self.attachedRigidbody;
            if (rb != null && rb.entity != e) SendTo(rb.entity, other, kind, c);
        }

        // Each behaviour still live when its turn comes (an earlier one may destroy or deactivate).
        static void SendTo(Entity e, Collider other, ContactEventKind kind, Collision? c)
        {
            List<Component> cs = e.Components;
            for (int k = 0; k < cs.Count; k++)
                if (cs[k] is Behaviour b && !b.isDestroyed && e.activeInHierarchy) b.SendContact(kind, other, c);
        }

        // Copies the points of the pair's manifolds, seen from self; false when the world has no
        // contact for the pair.
        bool AddManifoldPoints(Collision c, in ContactEvent e, Collider self, Collider other, bool selfIsA)
        {
            if (!_world.IsValid(e.ShapeA) || !_world.IsValid(e.ShapeB)) return false;
            ContactGraph g = _world.ContactGraph;
            int k = g.Find(e.ShapeA.Index, e.ShapeB.Index);
            if (k < 0) return false;
            for (int m = g.Contacts[k].FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                Vector3 n = selfIsA ? -mf.Normal : mf.Normal;
                for (int i = 0; i < mf.PointCount; i++)
                {
                    ref Fulcrum.Collision.ContactPoint p = ref ContactManifold.Point(ref mf, i);
                    c.AddContact(new ContactPoint
                    {
                        point = p.Position,
                        normal = n,
                        separation = p.Separation,
                        impulse = n * p.AppliedImpulse,
                        thisCollider = self,
                        otherCollider = other,
                    });
                }
            }
            return true;
        }

        // A destroyed entity hears nothing more; an inactive one neither (its shapes are gone).
        static bool Receives(Collider c) => !c.isDestroyed && !c.entity.isDestroyed && c.entity.activeInHierarchy;

        void ThrowIfDispatching(string what)
        {
            if (_dispatching != null)
                throw new InvalidOperationException($"{what} is not allowed from {_dispatching}: the scene is dispatching physics messages; use Destroy, which runs at the end of the frame.");
        }
    }
}
