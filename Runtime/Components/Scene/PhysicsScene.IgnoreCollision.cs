using System;
using System.Collections.Generic;

namespace Fulcrum.Components
{
    public sealed partial class PhysicsScene
    {
        readonly List<KeyValuePair<Collider, Collider>> _ignoredPairs = new List<KeyValuePair<Collider, Collider>>();

        /// <summary>
        /// Makes two colliders ignore each other (no contacts, no trigger messages) or collide
        /// again (Unity's Physics.IgnoreCollision). As in Unity the setting is forgotten when
        /// either collider is deactivated or destroyed; it survives the collider being rebuilt
        /// (a size or centre change). Ignoring ends their current contacts.
        /// </summary>
        public void IgnoreCollision(Collider collider1, Collider collider2, bool ignore = true)
        {
            if (collider1 == null) throw new ArgumentNullException(nameof(collider1));
            if (collider2 == null) throw new ArgumentNullException(nameof(collider2));
            if (collider1 == collider2) throw new ArgumentException($"IgnoreCollision needs two colliders; both are {collider1}.", nameof(collider2));
            if (collider1.scene != this || collider2.scene != this) throw new ArgumentException("IgnoreCollision: both colliders must belong to this scene.");
            if (collider1.isDestroyed || collider2.isDestroyed) throw new InvalidOperationException("IgnoreCollision: a collider has been destroyed.");
            if (_world.IsStepping) throw new InvalidOperationException("PhysicsScene.IgnoreCollision cannot be called while the world steps.");
            int k = FindIgnored(collider1, collider2);
            if (ignore == (k >= 0)) return;
            if (ignore) _ignoredPairs.Add(new KeyValuePair<Collider, Collider>(collider1, collider2));
            else _ignoredPairs.RemoveAt(k);
            if (collider1.HasShape && collider2.HasShape) _world.IgnoreCollision(collider1.shape, collider2.shape, ignore);
        }

        /// <summary>Whether the two colliders ignore each other (<see cref="IgnoreCollision"/>).</summary>
        public bool GetIgnoreCollision(Collider collider1, Collider collider2) => FindIgnored(collider1, collider2) >= 0;

        int FindIgnored(Collider a, Collider b)
        {
            for (int k = 0; k < _ignoredPairs.Count; k++)
            {
                KeyValuePair<Collider, Collider> p = _ignoredPairs[k];
                if ((p.Key == a && p.Value == b) || (p.Key == b && p.Value == a)) return k;
            }
            return -1;
        }

        // A rebuilt shape is a new shape to the world: it gets its collider's ignored pairs back.
        internal void ReapplyIgnores(Collider c)
        {
            for (int k = 0; k < _ignoredPairs.Count; k++)
            {
                KeyValuePair<Collider, Collider> p = _ignoredPairs[k];
                Collider? other = p.Key == c ? p.Value : p.Value == c ? p.Key : null;
                if (other != null && other.HasShape && c.HasShape) _world.IgnoreCollision(c.shape, other.shape);
            }
        }

        // Deactivated or destroyed: forgotten, as in Unity.
        internal void ForgetIgnores(Collider c)
        {
            for (int k = _ignoredPairs.Count - 1; k >= 0; k--)
                if (_ignoredPairs[k].Key == c || _ignoredPairs[k].Value == c) _ignoredPairs.RemoveAt(k);
        }
    }
}
