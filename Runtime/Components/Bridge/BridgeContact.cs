using System.Numerics;
using Fulcrum.Collision;

namespace Fulcrum.Components
{
    /// <summary>
    /// A contact or trigger event between bridged entities, delivered after the step that
    /// produced it (<see cref="IBridgeContactListener"/>), in the world's deterministic order
    /// (by shape pair). A value type: delivering it allocates nothing.
    /// </summary>
    public struct BridgeContact
    {
        /// <summary>Begin, persist or end.</summary>
        public ContactEventKind Kind;
        /// <summary>True when one side is a sensor (trigger): no physical response, no points.</summary>
        public bool IsTrigger;
        /// <summary>First entity's proxy (None when the body is not bridged).</summary>
        public ProxyHandle ProxyA;
        /// <summary>Second entity's proxy (None when the body is not bridged).</summary>
        public ProxyHandle ProxyB;
        /// <summary>First entity (kept for end events after it was unregistered), or null.</summary>
        public IPhysicsEntity? EntityA;
        /// <summary>Second entity, or null.</summary>
        public IPhysicsEntity? EntityB;
        /// <summary>World normal from A to B (zero for triggers and end events).</summary>
        public Vector3 Normal;
        /// <summary>Average contact point, world, metres.</summary>
        public Vector3 Point;
        /// <summary>Number of points in the contact's manifolds (0 for triggers and end events).</summary>
        public int PointCount;
        /// <summary>Where this event's points start in the batch's point buffer (read them with <see cref="PhysicsBridge.GetPoints"/>).</summary>
        public int FirstPoint;
        /// <summary>How many points the buffer holds for this event (0 when the world had no live contact to read them from).</summary>
        public int StoredPoints;
        /// <summary>Sum of the normal impulses the solver applied in the step, N s (B received +Normal times this).</summary>
        public float NormalImpulse;
        /// <summary>Velocity of B relative to A at the contact before the solve, m/s.</summary>
        public Vector3 RelativeVelocity;
        /// <summary>The world step that produced the event.</summary>
        public long StepIndex;
        /// <summary>Simulated time at the end of that step, seconds.</summary>
        public double Time;
    }
}
