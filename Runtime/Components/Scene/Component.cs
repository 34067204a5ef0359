using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// Something attached to an <see cref="Entity"/>, like Unity's Component. Add one with
    /// <see cref="Entity.AddComponent{T}"/>; never construct it yourself and keep it.
    /// </summary>
    public abstract class Component
    {
        Entity? _entity;

        /// <summary>The entity this component is attached to.</summary>
        public Entity entity => _entity ?? throw new InvalidOperationException($"{GetType().Name} is not attached to an entity: create components with Entity.AddComponent<T>().");

        /// <summary>The entity's transform.</summary>
        public Transform transform => entity.transform;

        /// <summary>The entity's name.</summary>
        public string name => entity.name;

        /// <summary>The scene of the entity.</summary>
        public PhysicsScene scene => entity.scene;

        /// <summary>True once the component (or its entity) has been destroyed.</summary>
        public bool isDestroyed { get; private set; }

        /// <summary>The first component of type <typeparamref name="T"/> on the same entity, or null.</summary>
        public T? GetComponent<T>() where T : class => entity.GetComponent<T>();

        /// <summary>The first component of type <typeparamref name="T"/> on the entity or its nearest ancestor with one, or null.</summary>
        public T? GetComponentInParent<T>() where T : class => entity.GetComponentInParent<T>();

        /// <summary>"TypeName on 'entity'": how errors name a component.</summary>
        public override string ToString() => _entity == null ? GetType().Name : $"{GetType().Name} on '{_entity.name}'";

        internal void Attach(Entity e) => _entity = e;

        internal void MarkDestroyed() => isDestroyed = true;

        internal void ThrowIfDestroyed()
        {
            if (isDestroyed) throw new InvalidOperationException($"{this} has been destroyed.");
        }

        /// <summary>
        /// Refuses a change to <paramref name="member"/> of a destroyed component, or one made
        /// while the world steps: the step reads the settings it started with.
        /// </summary>
        internal void ThrowIfStepping(string member)
        {
            ThrowIfDestroyed();
            if (entity.scene.world.IsStepping)
                throw new InvalidOperationException($"{this}: {member} cannot be changed while the world steps (from a callback inside World.Step); do it in FixedUpdate or in a collision message, which run after the step.");
        }

        /// <summary>
        /// The head of a setter for a finite, non-negative setting (damping, friction): checks
        /// <paramref name="value"/> (naming <paramref name="member"/>), refuses the change while
        /// the world steps, and stores it; the caller then hands it to the live object.
        /// </summary>
        internal void SetNonNegative(ref float field, float value, string member)
        {
            FieldCheck.NonNegative(value, this, member);
            ThrowIfStepping(member);
            field = value;
        }

        /// <summary>
        /// The head of a setter for a flag whose change must be applied (a rebuild, a new body
        /// type): refuses the change while the world steps; false when <paramref name="field"/>
        /// already holds <paramref name="value"/>, else stores it and returns true.
        /// </summary>
        internal bool SetFlag(ref bool field, bool value, string member)
        {
            ThrowIfStepping(member);
            if (value == field) return false;
            field = value;
            return true;
        }

        /// <summary>True when the entity is active in the hierarchy and the component not destroyed.</summary>
        internal bool IsLive => _entity != null && !isDestroyed && _entity.activeInHierarchy;

        /// <summary>Called once, right after the component joins its entity, before activation: may refuse it by throwing.</summary>
        internal virtual void OnAdded() { }

        /// <summary>The entity became active in the hierarchy (or the component was added to an active one).</summary>
        internal virtual void Activate() { }

        /// <summary>The entity stopped being active in the hierarchy.</summary>
        internal virtual void Deactivate() { }

        /// <summary>Final teardown when the component is destroyed (after <see cref="Deactivate"/> when it was live).</summary>
        internal virtual void Teardown() { }
    }
}
