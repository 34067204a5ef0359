using System;
using System.Numerics;

namespace Fulcrum.Components
{
    /// <summary>
    /// What OnCollisionEnter/Stay/Exit receive, seen from the receiving collider (Unity's
    /// Collision). One object is reused for every message of a scene, so that dispatch
    /// allocates nothing: read it inside the message and copy what you keep (Unity's
    /// Physics.reuseCollisionCallbacks = true).
    /// Sign conventions: <see cref="ContactPoint.normal"/> points from the other collider
    /// towards this one; <see cref="impulse"/> is the impulse applied to this collider's body;
    /// <see cref="relativeVelocity"/> is the other body's velocity minus this one's at the
    /// contact (Unity does not document its sign; for a ball landing on the ground it points up
    /// in the ball's message, as in Unity).
    /// </summary>
    public sealed class Collision
    {
        // Up to four manifolds of four points each for one pair of shapes.
        internal const int MaxContacts = 16;
        readonly ContactPoint[] _contacts = new ContactPoint[MaxContacts];
        int _count;

        internal Collision() { }

        /// <summary>The other collider.</summary>
        public Collider collider { get; internal set; } = null!;

        /// <summary>The receiving collider.</summary>
        public Collider thisCollider { get; internal set; } = null!;

        /// <summary>The other collider's rigidbody, or null when it is static.</summary>
        public Rigidbody? rigidbody => collider.attachedRigidbody;

        /// <summary>The other collider's entity (Unity's gameObject).</summary>
        public Entity entity => collider.entity;

        /// <summary>The other collider's transform.</summary>
        public Transform transform => collider.transform;

        /// <summary>Total impulse applied to this collider's body by the contact in the step, N s (zero on exit).</summary>
        public Vector3 impulse { get; internal set; }

        /// <summary>Velocity of the other body relative to this one at the contact, m/s (before the solve).</summary>
        public Vector3 relativeVelocity { get; internal set; }

        /// <summary>Number of contact points (0 on exit).</summary>
        public int contactCount => _count;

        /// <summary>Contact point <paramref name="index"/> (0 .. contactCount-1).</summary>
        public ContactPoint GetContact(int index)
        {
            if ((uint)index >= (uint)_count)
                throw new ArgumentOutOfRangeException(nameof(index), $"Collision has {_count} contacts; index {index} is out of range.");
            return _contacts[index];
        }

        /// <summary>Copies the contact points into <paramref name="into"/>; returns how many were copied.</summary>
        public int GetContacts(Span<ContactPoint> into)
        {
            int n = Math.Min(into.Length, _count);
            for (int k = 0; k < n; k++) into[k] = GetContact(k);
            return n;
        }

        internal void Reset(Collider self, Collider other, Vector3 impulse, Vector3 relativeVelocity)
        {
            thisCollider = self;
            collider = other;
            this.impulse = impulse;
            this.relativeVelocity = relativeVelocity;
            _count = 0;
        }

        internal void AddContact(in ContactPoint p)
        {
            if (_count < MaxContacts) _contacts[_count++] = p;
        }
    }
}
