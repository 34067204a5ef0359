using System;
using System.Collections.Generic;

namespace Fulcrum.Components
{
    /// <summary>
    /// A thing in a <see cref="PhysicsScene"/>, like Unity's GameObject: a name, a
    /// <see cref="Transform"/>, a layer, an active flag and a list of components. Create it
    /// with <see cref="PhysicsScene.CreateEntity"/>; remove it with
    /// <see cref="PhysicsScene.Destroy(Entity)"/>. Unity's "destroyed object equals null"
    /// trick has no C# equivalent here: test <see cref="isDestroyed"/>.
    /// </summary>
    public sealed class Entity
    {
        readonly PhysicsScene _scene;
        readonly Transform _transform;
        internal readonly List<Component> Components = new List<Component>();
        string _name;
        int _layer;
        bool _activeSelf = true;
        bool _activeInHierarchy;

        internal Entity(PhysicsScene scene, string name)
        {
            _scene = scene;
            _name = name;
            _transform = new Transform(this);
        }

        /// <summary>The scene the entity lives in.</summary>
        public PhysicsScene scene => _scene;

        /// <summary>The name (used in errors and traces).</summary>
        public string name
        {
            get => _name;
            set => _name = value ?? throw new ArgumentNullException(nameof(name), "Entity.name cannot be null.");
        }

        /// <summary>Position and rotation, with an optional parent.</summary>
        public Transform transform => _transform;

        /// <summary>
        /// The collision layer, 0..31. Colliders collide only with layers the scene's layer
        /// matrix allows (<see cref="PhysicsScene.IgnoreLayerCollision"/>); queries filter by
        /// layer mask. Setting it updates the entity's colliders.
        /// </summary>
        public int layer
        {
            get => _layer;
            set
            {
                if ((uint)value > 31) throw new ArgumentException($"Entity '{_name}': layer must be in 0..31, got {value}.", nameof(layer));
                if (value == _layer) return;
                _layer = value;
                for (int k = 0; k < Components.Count; k++)
                    if (Components[k] is Collider c) c.OnLayerChanged();
            }
        }

        /// <summary>The entity's own active flag (Unity's activeSelf).</summary>
        public bool activeSelf => _activeSelf;

        /// <summary>True when the entity and all its ancestors are active: only then do its components run and simulate.</summary>
        public bool activeInHierarchy => _activeInHierarchy;

        /// <summary>True once <see cref="PhysicsScene.Destroy(Entity)"/> has taken effect.</summary>
        public bool isDestroyed { get; internal set; }

        /// <summary>True while a destroy is pending for the end of the frame.</summary>
        internal bool DestroyPending { get; set; }

        /// <summary>
        /// Activates or deactivates the entity (and so its children). Deactivating calls
        /// OnDisable and removes its bodies and shapes from the world; activating calls Awake
        /// (the first time) and OnEnable, and recreates them.
        /// </summary>
        public void SetActive(bool value)
        {
            ThrowIfDestroyed();
            if (value == _activeSelf) return;
            _activeSelf = value;
            RefreshActive();
        }

        /// <summary>
        /// Adds a component of type <typeparamref name="T"/>. On an active entity its Awake and
        /// OnEnable run before this returns and its Start before its first FixedUpdate or
        /// Update, as in Unity.
        /// </summary>
        public T AddComponent<T>() where T : Component, new()
        {
            ThrowIfDestroyed();
            var c = new T();
            c.Attach(this);
            Components.Add(c);
            try
            {
                c.OnAdded();
                _scene.Register(c);
                if (_activeInHierarchy) c.Activate();
            }
            catch
            {
                // A component that refuses its entity (a second Rigidbody, say) is not kept.
                Components.Remove(c);
                c.MarkDestroyed();
                throw;
            }
            return c;
        }

        /// <summary>The first component of type <typeparamref name="T"/>, or null.</summary>
        public T? GetComponent<T>() where T : class
        {
            for (int k = 0; k < Components.Count; k++)
                if (Components[k] is T t && !Components[k].isDestroyed) return t;
            return null;
        }

        /// <summary>Like <see cref="GetComponent{T}"/>, as a try-pattern.</summary>
        public bool TryGetComponent<T>(out T component) where T : class
        {
            T? c = GetComponent<T>();
            component = c!;
            return c != null;
        }

        /// <summary>Appends every component of type <typeparamref name="T"/> to <paramref name="results"/>; returns how many were added.</summary>
        public int GetComponents<T>(List<T> results) where T : class
        {
            int n = 0;
            for (int k = 0; k < Components.Count; k++)
                if (Components[k] is T t && !Components[k].isDestroyed) { results.Add(t); n++; }
            return n;
        }

        /// <summary>The first component of type <typeparamref name="T"/> on this entity or its nearest ancestor that has one, or null.</summary>
        public T? GetComponentInParent<T>() where T : class
        {
            for (Transform? t = _transform; t != null; t = t.parent)
            {
                T? c = t.entity.GetComponent<T>();
                if (c != null) return c;
            }
            return null;
        }

        /// <inheritdoc/>
        public override string ToString() => $"Entity '{_name}'";

        internal void ThrowIfDestroyed()
        {
            if (isDestroyed) throw new InvalidOperationException($"Entity '{_name}' has been destroyed.");
        }

        // Recomputes activeInHierarchy for this entity and its descendants, running the
        // activation or deactivation of components whose state changes.
        internal void RefreshActive()
        {
            Transform? p = _transform.parent;
            bool now = _activeSelf && !isDestroyed && (p == null || p.entity._activeInHierarchy);
            if (now != _activeInHierarchy)
            {
                _activeInHierarchy = now;
                for (int k = 0; k < Components.Count; k++)
                {
                    Component c = Components[k];
                    if (c.isDestroyed) continue;
                    if (now) c.Activate();
                    else c.Deactivate();
                }
            }
            List<Transform> children = _transform.Children;
            for (int k = 0; k < children.Count; k++) children[k].entity.RefreshActive();
        }

        // The parent changed: activity may change, and colliders may belong to another body.
        internal void OnHierarchyChanged()
        {
            RefreshActive();
            _scene.OnHierarchyChanged(this);
        }
    }
}
