using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// The headless host of the component model: a <see cref="World"/>, the entities and
    /// their components, and the frame loop (<see cref="Tick"/>) that calls the MonoBehaviour
    /// messages in Unity's order around fixed physics steps. Not thread-safe: one thread
    /// drives it. Inside Unity the adapter (Fulcrum.Unity) drives the same scene from
    /// Unity's own FixedUpdate and Update through <see cref="Simulate"/> and
    /// <see cref="ShowInterpolatedPoses"/>.
    /// </summary>
    public sealed partial class PhysicsScene
    {
        readonly World _world;
        readonly FixedStepper _stepper;
        readonly List<Entity> _entities = new List<Entity>();
        readonly List<Behaviour> _behaviours = new List<Behaviour>();
        readonly List<Behaviour> _startQueue = new List<Behaviour>();
        readonly List<Rigidbody> _rigidbodies = new List<Rigidbody>();
        readonly List<Collider> _colliders = new List<Collider>();
        readonly List<Entity> _destroyEntities = new List<Entity>();
        readonly List<Component> _destroyComponents = new List<Component>();
        readonly uint[] _layerCollides = new uint[32];
        bool _needsCompaction;

        /// <summary>A scene with default world settings and Unity's default fixed step (0.02 s).</summary>
        public PhysicsScene() : this(WorldSettings.Default) { }

        /// <summary>
        /// A scene over a new world with <paramref name="settings"/>, stepping every
        /// <paramref name="fixedDeltaTime"/> seconds and at most <paramref name="maxStepsPerFrame"/>
        /// times per frame (the rest of a long frame is dropped, as Unity's maximumDeltaTime does).
        /// </summary>
        public PhysicsScene(WorldSettings settings, float fixedDeltaTime = 0.02f, int maxStepsPerFrame = 8)
        {
            _world = new World(settings);
            _stepper = new FixedStepper(fixedDeltaTime, maxStepsPerFrame);
            for (int k = 0; k < 32; k++) _layerCollides[k] = uint.MaxValue;
        }

        /// <summary>The world the components live in (read it freely; change bodies through the components).</summary>
        public World world => _world;

        /// <summary>The fixed physics step, seconds.</summary>
        public float fixedDeltaTime => _stepper.FixedDt;

        /// <summary>
        /// The time step of the current message, seconds: <see cref="fixedDeltaTime"/> inside
        /// FixedUpdate and the physics messages, the frame time elsewhere (Unity's Time.deltaTime).
        /// </summary>
        public float deltaTime => _inFixedPhase ? _stepper.FixedDt : _frameDt;

        /// <summary>Time at the start of this frame, seconds (the sum of frame times; Unity's Time.time).</summary>
        public double time { get; private set; }

        /// <summary>Simulated time, seconds (Unity's Time.fixedTime).</summary>
        public double fixedTime => _world.Time;

        /// <summary>Frames ticked so far.</summary>
        public long frameCount { get; private set; }

        /// <summary>Where the render time lies between the last two steps, in [0, 1).</summary>
        public float interpolationFactor => _stepper.InterpolationFactor;

        /// <summary>Entities alive in the scene (destroyed ones leave at the end of the frame).</summary>
        public int entityCount => _entities.Count;

        /// <summary>Creates an active entity at the world origin (or at <paramref name="position"/>), optionally under a parent.</summary>
        public Entity CreateEntity(string name, Vector3 position = default, Quaternion? rotation = null, Entity? parent = null)
        {
            if (name == null) throw new ArgumentNullException(nameof(name), "PhysicsScene.CreateEntity: name cannot be null.");
            Validate.Finite(position, $"Entity '{name}': position");
            Quaternion q = Validate.Rotation(rotation ?? Quaternion.Identity, $"Entity '{name}': rotation");
            if (parent != null && (parent.scene != this || parent.isDestroyed))
                throw new ArgumentException($"Entity '{name}': parent '{parent.name}' is destroyed or belongs to another scene.", nameof(parent));
            var e = new Entity(this, name);
            _entities.Add(e);
            if (parent != null) e.transform.SetParent(parent.transform, false);
            e.transform.SetWorldPoseSilently(new Pose(position, q));
            e.RefreshActive();
            return e;
        }

        /// <summary>
        /// Destroys an entity, its children and their components at the end of the current
        /// frame (as Unity's Destroy): OnDisable, then OnDestroy, then its bodies leave the world.
        /// Until then it behaves as before.
        /// </summary>
        public void Destroy(Entity entity)
        {
            if (entity == null) throw new ArgumentNullException(nameof(entity));
            if (entity.isDestroyed || entity.DestroyPending) return;
            entity.DestroyPending = true;
            _destroyEntities.Add(entity);
        }

        /// <summary>Destroys one component at the end of the current frame.</summary>
        public void Destroy(Component component)
        {
            if (component == null) throw new ArgumentNullException(nameof(component));
            if (component.isDestroyed || _destroyComponents.Contains(component)) return;
            _destroyComponents.Add(component);
        }

        /// <summary>
        /// Destroys an entity now. Not allowed while physics messages are being dispatched
        /// (use <see cref="Destroy(Entity)"/> there), as in Unity.
        /// </summary>
        public void DestroyImmediate(Entity entity)
        {
            if (entity == null) throw new ArgumentNullException(nameof(entity));
            ThrowIfDispatching($"DestroyImmediate(Entity '{entity.name}')");
            DestroyEntityNow(entity);
        }

        /// <summary>Destroys one component now (not while physics messages are being dispatched).</summary>
        public void DestroyImmediate(Component component)
        {
            if (component == null) throw new ArgumentNullException(nameof(component));
            ThrowIfDispatching($"DestroyImmediate({component})");
            DestroyComponentNow(component);
        }

        /// <summary>
        /// Makes colliders on layers <paramref name="layer1"/> and <paramref name="layer2"/>
        /// ignore each other (or collide again), like Unity's Physics.IgnoreLayerCollision.
        /// Applies to existing colliders at once.
        /// </summary>
        public void IgnoreLayerCollision(int layer1, int layer2, bool ignore = true)
        {
            CheckLayer(layer1, nameof(layer1));
            CheckLayer(layer2, nameof(layer2));
            if (_world.IsStepping) throw new InvalidOperationException("PhysicsScene.IgnoreLayerCollision cannot be called while the world steps.");
            SetBit(layer1, layer2, !ignore);
            SetBit(layer2, layer1, !ignore);
            ShapeStorage shapes = _world.Shapes;
            for (int k = 0; k < _colliders.Count; k++)
            {
                Collider c = _colliders[k];
                if (c.HasShape) shapes.CollidesWith[c.shape.Index] = _layerCollides[c.entity.layer];
            }
        }

        /// <summary>True when the two layers ignore each other.</summary>
        public bool GetIgnoreLayerCollision(int layer1, int layer2)
        {
            CheckLayer(layer1, nameof(layer1));
            CheckLayer(layer2, nameof(layer2));
            return (_layerCollides[layer1] & (1u << layer2)) == 0;
        }

        internal uint CollisionMaskOf(int layer) => _layerCollides[layer];

        void SetBit(int a, int b, bool on)
        {
            if (on) _layerCollides[a] |= 1u << b;
            else _layerCollides[a] &= ~(1u << b);
        }

        static void CheckLayer(int layer, string name)
        {
            if ((uint)layer > 31) throw new ArgumentException($"{name} must be in 0..31, got {layer}.", name);
        }

        internal void Register(Component c)
        {
            switch (c)
            {
                case Behaviour b:
                    b.UpdateIndex = _behaviours.Count;
                    _behaviours.Add(b);
                    break;
                case Rigidbody rb:
                    _rigidbodies.Add(rb);
                    break;
                case Collider col:
                    _colliders.Add(col);
                    break;
            }
        }

        internal void QueueStart(Behaviour b)
        {
            b.StartQueued = true;
            _startQueue.Add(b);
        }

        // A rigidbody got its body: colliders below it that belong to it now (static so far, or
        // on an ancestor's body) move onto it.
        internal void OnRigidbodyActivated(Rigidbody rb) => ReattachColliders(rb.transform);

        // A rigidbody lost its body: its colliders fall back to the next rigidbody up or to
        // static bodies, then the body goes.
        internal void OnRigidbodyDeactivated(Rigidbody rb, BodyHandle oldBody)
        {
            for (int k = rb.Colliders.Count - 1; k >= 0; k--)
            {
                Collider c = rb.Colliders[k];
                c.Remove();
                if (c.IsLive && c.enabled) c.Build();
            }
            _world.DestroyBody(oldBody);
        }

        internal void OnHierarchyChanged(Entity e) => ReattachColliders(e.transform);

        void ReattachColliders(Transform root)
        {
            List<Component> cs = root.entity.Components;
            for (int k = 0; k < cs.Count; k++)
            {
                if (cs[k] is Collider c && c.HasShape && c.attachedRigidbody != NearestLiveRigidbody(c.transform))
                {
                    c.Remove();
                    c.Build();
                }
            }
            List<Transform> children = root.Children;
            for (int k = 0; k < children.Count; k++) ReattachColliders(children[k]);
        }

        static Rigidbody? NearestLiveRigidbody(Transform t)
        {
            for (Transform? p = t; p != null; p = p.parent)
            {
                Rigidbody? rb = p.entity.GetComponent<Rigidbody>();
                if (rb != null && rb.HasBody) return rb;
            }
            return null;
        }

        void DestroyEntityNow(Entity e)
        {
            if (e.isDestroyed) return;
            e.isDestroyed = true;
            e.RefreshActive();
            TeardownTree(e.transform);
            e.transform.DetachFromParentForDestroy();
            _needsCompaction = true;
        }

        void TeardownTree(Transform t)
        {
            Entity e = t.entity;
            e.isDestroyed = true;
            List<Component> cs = e.Components;
            for (int k = 0; k < cs.Count; k++)
            {
                if (cs[k].isDestroyed) continue;
                cs[k].Teardown();
                cs[k].MarkDestroyed();
            }
            List<Transform> children = t.Children;
            for (int k = 0; k < children.Count; k++) TeardownTree(children[k]);
        }

        void DestroyComponentNow(Component c)
        {
            if (c.isDestroyed) return;
            if (c.IsLive) c.Deactivate();
            c.Teardown();
            c.MarkDestroyed();
            c.entity.Components.Remove(c);
            _needsCompaction = true;
        }

        // Runs pending destroys (end of frame), then drops destroyed entries from the lists,
        // keeping the survivors in their order (update order is creation order).
        void ProcessDestroys()
        {
            // Destroys requested by OnDestroy run in the same pass.
            for (int k = 0; k < _destroyComponents.Count; k++) DestroyComponentNow(_destroyComponents[k]);
            for (int k = 0; k < _destroyEntities.Count; k++) DestroyEntityNow(_destroyEntities[k]);
            for (int k = 0; k < _destroyComponents.Count; k++) DestroyComponentNow(_destroyComponents[k]);
            _destroyComponents.Clear();
            _destroyEntities.Clear();
            if (!_needsCompaction) return;
            _needsCompaction = false;
            _entities.RemoveAll(IsDestroyedEntity);
            _rigidbodies.RemoveAll(IsDestroyedComponent);
            _colliders.RemoveAll(IsDestroyedComponent);
            _behaviours.RemoveAll(IsDestroyedComponent);
            _joints.RemoveAll(IsDestroyedComponent);
            _startQueue.RemoveAll(IsDestroyedComponent);
            for (int k = 0; k < _behaviours.Count; k++) _behaviours[k].UpdateIndex = k;
        }

        static readonly Predicate<Entity> IsDestroyedEntity = e => e.isDestroyed;
        static readonly Predicate<Component> IsDestroyedComponent = c => c.isDestroyed;
    }
}
