using Fulcrum.Collision;

namespace Fulcrum.Components
{
    /// <summary>
    /// A scripted component with the MonoBehaviour lifecycle. Override the messages you need;
    /// the host (<see cref="PhysicsScene.Tick"/>) calls them in Unity's documented order:
    /// Awake and OnEnable when the component goes live, Start before its first FixedUpdate or
    /// Update, then each frame FixedUpdate (zero or more times, each followed by the physics
    /// step and the collision and trigger messages), Update and LateUpdate; OnDisable and
    /// OnDestroy when it is disabled or destroyed.
    /// Departures from Unity: messages are virtual methods (no reflection), and an exception
    /// thrown by a message propagates out of Tick instead of being logged.
    /// As in Unity, collision and trigger messages also reach disabled behaviours (so that a
    /// collision can enable one), but not those of inactive entities.
    /// </summary>
    public abstract class Behaviour : Component
    {
        bool _enabled = true;
        internal bool Awoken;
        internal bool Started;
        internal bool StartQueued;
        // True between OnEnable and OnDisable: the state the last message left it in.
        internal bool EnabledCalled;
        /// <summary>The index in the scene's update list (for swap-free removal at the end of a frame).</summary>
        internal int UpdateIndex = -1;

        /// <summary>Enabled behaviours get updates; changing it calls OnEnable/OnDisable on a live entity.</summary>
        public bool enabled
        {
            get => _enabled;
            set
            {
                ThrowIfDestroyed();
                if (value == _enabled) return;
                _enabled = value;
                if (!IsLive || !Awoken) return;
                if (value) EnableNow();
                else DisableNow();
            }
        }

        /// <summary>True when enabled and the entity is active in the hierarchy.</summary>
        public bool isActiveAndEnabled => _enabled && IsLive;

        /// <summary>Called once, when the component first goes live (even if disabled).</summary>
        protected virtual void Awake() { }

        /// <summary>Called each time the component becomes enabled and active.</summary>
        protected virtual void OnEnable() { }

        /// <summary>Called once, before the first FixedUpdate or Update after the component is enabled.</summary>
        protected virtual void Start() { }

        /// <summary>Called before each physics step; read <see cref="PhysicsScene.fixedDeltaTime"/>.</summary>
        protected virtual void FixedUpdate() { }

        /// <summary>Called once per frame after the physics steps; read <see cref="PhysicsScene.deltaTime"/>.</summary>
        protected virtual void Update() { }

        /// <summary>Called once per frame after every Update.</summary>
        protected virtual void LateUpdate() { }

        /// <summary>Called when the component stops being enabled and active.</summary>
        protected virtual void OnDisable() { }

        /// <summary>Called when the component is destroyed (only if Awake ran).</summary>
        protected virtual void OnDestroy() { }

        /// <summary>
        /// A collider of this entity (or a child collider of its rigidbody) started touching
        /// another. The <see cref="Collision"/> object is reused for every message: copy what
        /// you keep (Unity's reuseCollisionCallbacks).
        /// </summary>
        protected virtual void OnCollisionEnter(Collision collision) { }

        /// <summary>Called after each step while the contact persists; the argument is reused.</summary>
        protected virtual void OnCollisionStay(Collision collision) { }

        /// <summary>The contact ended (or the other collider was removed); the argument is reused.</summary>
        protected virtual void OnCollisionExit(Collision collision) { }

        /// <summary>A trigger collider and another collider started overlapping.</summary>
        protected virtual void OnTriggerEnter(Collider other) { }

        /// <summary>Called after each step while the overlap persists.</summary>
        protected virtual void OnTriggerStay(Collider other) { }

        /// <summary>The overlap ended (or the other collider was removed).</summary>
        protected virtual void OnTriggerExit(Collider other) { }

        /// <summary>A joint on this entity broke; <paramref name="breakForce"/> is the force that broke it, N.</summary>
        protected virtual void OnJointBreak(float breakForce) { }

        internal override void Activate()
        {
            if (!Awoken)
            {
                Awoken = true;
                Awake();
                // Awake may have destroyed or deactivated its own entity.
                if (!IsLive) return;
            }
            if (_enabled) EnableNow();
        }

        internal override void Deactivate()
        {
            if (EnabledCalled) DisableNow();
        }

        internal override void Teardown()
        {
            if (Awoken) OnDestroy();
        }

        void EnableNow()
        {
            EnabledCalled = true;
            OnEnable();
            if (!Started && !StartQueued) scene.QueueStart(this);
        }

        void DisableNow()
        {
            EnabledCalled = false;
            OnDisable();
        }

        internal void RunStart()
        {
            Started = true;
            Start();
        }

        internal void RunFixedUpdate() => FixedUpdate();

        /// <summary>
        /// One contact message of <paramref name="kind"/>: OnCollisionEnter/Stay/Exit with
        /// <paramref name="collision"/> when there is one, OnTriggerEnter/Stay/Exit with
        /// <paramref name="other"/> otherwise.
        /// </summary>
        internal void SendContact(ContactEventKind kind, Collider other, Collision? collision)
        {
            if (collision != null)
            {
                if (kind == ContactEventKind.Begin) OnCollisionEnter(collision);
                else if (kind == ContactEventKind.Persist) OnCollisionStay(collision);
                else OnCollisionExit(collision);
            }
            else if (kind == ContactEventKind.Begin) OnTriggerEnter(other);
            else if (kind == ContactEventKind.Persist) OnTriggerStay(other);
            else OnTriggerExit(other);
        }
        internal void SendJointBreak(float force) => OnJointBreak(force);
        internal void RunUpdate() => Update();
        internal void RunLateUpdate() => LateUpdate();
    }
}
