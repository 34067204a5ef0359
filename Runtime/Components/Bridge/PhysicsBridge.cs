using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// Loose coupling between a custom engine and a <see cref="World"/> (the "loose" mode of
    /// the design): the engine keeps its own objects, registers them here
    /// (<see cref="IPhysicsEntity"/>), and once per frame calls <see cref="SyncFromGame"/>
    /// (game-driven poses in), <see cref="Step"/> (fixed steps from an accumulator, contact
    /// events delivered after each step) and <see cref="SyncToGame"/> (interpolated
    /// physics-driven poses out).
    /// With <see cref="PhysicsBridgeSettings.ThreadRateHz"/> &gt; 0 the world runs on its own
    /// thread at that rate; poses cross over through double buffers and events through a
    /// locked outbox, so the game thread never waits for a step. All public members are for
    /// the game thread. Steady-state frames allocate nothing.
    /// </summary>
    public sealed partial class PhysicsBridge : IDisposable
    {
        const byte Free = 0, Live = 1, Removing = 2;

        readonly World _world;
        readonly PhysicsBridgeSettings _settings;
        readonly FixedStepper _stepper;
        readonly object _sync = new object();
        readonly bool _threaded;

        // Game side: owned by the game thread. A slot stays taken in _gSlots (its generation
        // unchanged) while Removing, until the world side has delivered its last events.
        readonly SlotAllocator _gSlots = new SlotAllocator();
        IPhysicsEntity?[] _gEntity = Array.Empty<IPhysicsEntity?>();
        byte[] _gState = Array.Empty<byte>();
        DriveMode[] _gMode = Array.Empty<DriveMode>();
        bool[] _gStatic = Array.Empty<bool>();
        Pose[] _gInput = Array.Empty<Pose>();
        int _liveCount;
        BridgeCommandQueue _commands = new BridgeCommandQueue();
        bool _dispatching;
        IBridgeContactListener? _listener;
        readonly ShapeDef[] _oneShape = new ShapeDef[1];

        /// <summary>A bridge over a new world with default settings, stepping on the caller's thread.</summary>
        public PhysicsBridge() : this(new World(), PhysicsBridgeSettings.Default) { }

        /// <summary>
        /// A bridge over <paramref name="world"/>. With a physics thread the bridge owns the world
        /// from now on: do not touch it from other threads until <see cref="Dispose"/>.
        /// </summary>
        public PhysicsBridge(World world, PhysicsBridgeSettings settings)
        {
            _world = world ?? throw new ArgumentNullException(nameof(world));
            settings.Validate();
            _settings = settings;
            _threaded = settings.ThreadRateHz > 0;
            float dt = _threaded ? 1f / settings.ThreadRateHz : settings.FixedDt;
            _stepper = new FixedStepper(dt, settings.MaxStepsPerFrame);
            if (settings.HapticsCapacity > 0) Haptics = new HapticStream(settings.HapticsCapacity);
            if (_threaded) StartThread();
        }

        /// <summary>
        /// The world. Only while no physics thread runs: with one, reading it from the game
        /// thread would race the step, so this throws.
        /// </summary>
        public World World
        {
            get
            {
                if (_threaded) throw new InvalidOperationException("PhysicsBridge.World is owned by the physics thread; use the bridge's methods (commands are applied between steps).");
                return _world;
            }
        }

        /// <summary>The fixed step, seconds (1 / ThreadRateHz with a physics thread).</summary>
        public float FixedDt => _stepper.FixedDt;

        /// <summary>True when the world runs on its own thread.</summary>
        public bool IsThreaded => _threaded;

        /// <summary>Registered entities (not yet unregistered).</summary>
        public int Count => _liveCount;

        /// <summary>Receives contact and trigger events on the game thread; null for none.</summary>
        public IBridgeContactListener? ContactListener
        {
            get => _listener;
            set => _listener = value;
        }

        /// <summary>Per-contact force samples for haptics (null when <see cref="PhysicsBridgeSettings.HapticsCapacity"/> is 0). Enable per entity with <see cref="SetHaptics"/>.</summary>
        public HapticStream? Haptics { get; }

        /// <summary>
        /// Registers <paramref name="entity"/> with a body built from <paramref name="body"/>
        /// (its pose is read from the entity, its type from <paramref name="mode"/>: Physics
        /// makes it dynamic, Game kinematic unless the def is static) and one shape.
        /// </summary>
        public ProxyHandle Register(IPhysicsEntity entity, in BodyDef body, in ShapeDef shape, DriveMode mode = DriveMode.Physics)
        {
            _oneShape[0] = shape;
            try { return Register(entity, body, _oneShape, mode); }
            finally { _oneShape[0] = default; }
        }

        /// <summary>
        /// Registers <paramref name="entity"/> with a body and any number of shapes (a compound).
        /// The body exists once this returns, except inside a contact callback or with a physics
        /// thread, where it is created before the next step. Everything is checked first.
        /// </summary>
        public ProxyHandle Register(IPhysicsEntity entity, in BodyDef body, ReadOnlySpan<ShapeDef> shapes, DriveMode mode = DriveMode.Physics)
        {
            ThrowIfDisposed();
            if (entity == null) throw new ArgumentNullException(nameof(entity), "PhysicsBridge.Register: entity cannot be null.");
            if (mode != DriveMode.Physics && mode != DriveMode.Game) throw new ArgumentException($"PhysicsBridge.Register: mode {mode} is not a DriveMode.", nameof(mode));
            if (mode == DriveMode.Physics && body.Type == BodyType.Static)
                throw new ArgumentException($"PhysicsBridge.Register: {entity} has a static body, which physics cannot drive; register it with DriveMode.Game.", nameof(mode));
            entity.GetPose(out Vector3 position, out Quaternion rotation);
            FieldCheck.Position(position, entity, "position");
            rotation = FieldCheck.Rotation(rotation, entity, "rotation");
            if (body.Mass < 0 || !float.IsFinite(body.Mass)) throw new ArgumentException($"PhysicsBridge.Register: {entity} body.Mass must be finite and >= 0, got {body.Mass}.", "Mass");

            BodyType type = mode == DriveMode.Physics ? BodyType.Dynamic : body.Type == BodyType.Static ? BodyType.Static : BodyType.Kinematic;
            for (int k = 0; k < shapes.Length; k++)
            {
                shapes[k].Validate();
                if (shapes[k].Geometry.IsStaticOnly && type != BodyType.Static)
                    throw new ArgumentException($"PhysicsBridge.Register: {entity} shapes[{k}] is a {shapes[k].Geometry.Type}, which only a static body may carry.", "shapes");
            }

            int slot = AllocateSlot();
            BodyDef def = body;
            def.Position = position;
            def.Rotation = rotation;
            def.Type = type;
            _gEntity[slot] = entity;
            _gState[slot] = Live;
            _gMode[slot] = mode;
            _gStatic[slot] = def.Type == BodyType.Static;
            _gInput[slot] = new Pose(position, rotation);
            _liveCount++;
            var cmd = new BridgeCommand { Kind = BridgeCommandKind.Create, Slot = slot, Generation = _gSlots.Generation[slot], Entity = entity, Body = def, Mode = mode };
            Enqueue(cmd, shapes);
            return new ProxyHandle(slot, _gSlots.Generation[slot], _world.Id);
        }

        /// <summary>
        /// Removes an entity's body. Inside a contact callback (or with a physics thread) the
        /// removal happens after the current batch of events; either way the entity hears no
        /// more begin or persist events, and end events for its contacts still name it.
        /// </summary>
        public void Unregister(ProxyHandle proxy)
        {
            int slot = LiveSlot(proxy, nameof(Unregister));
            _gState[slot] = Removing;
            _liveCount--;
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.Destroy, Slot = slot, Generation = proxy.Generation }, default);
        }

        /// <summary>True while <paramref name="proxy"/> names a registered entity.</summary>
        public bool IsRegistered(ProxyHandle proxy) =>
            proxy.WorldId == _world.Id && _gSlots.IsLive(proxy.Index, proxy.Generation) && _gState[proxy.Index] == Live;

        /// <summary>The entity of a registered proxy.</summary>
        public IPhysicsEntity GetEntity(ProxyHandle proxy) => _gEntity[LiveSlot(proxy, nameof(GetEntity))]!;

        /// <summary>Who drives the entity.</summary>
        public DriveMode GetDriveMode(ProxyHandle proxy) => _gMode[LiveSlot(proxy, nameof(GetDriveMode))];

        /// <summary>Hands an entity to the game (its body turns kinematic) or to physics (dynamic).</summary>
        public void SetDriveMode(ProxyHandle proxy, DriveMode mode)
        {
            int slot = LiveSlot(proxy, nameof(SetDriveMode));
            if (mode != DriveMode.Physics && mode != DriveMode.Game) throw new ArgumentException($"PhysicsBridge.SetDriveMode: mode {mode} is not a DriveMode.", nameof(mode));
            if (_gStatic[slot]) throw new InvalidOperationException($"PhysicsBridge.SetDriveMode: {_gEntity[slot]} has a static body; only dynamic and kinematic bodies change hands.");
            if (_gMode[slot] == mode) return;
            _gMode[slot] = mode;
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.SetMode, Slot = slot, Generation = proxy.Generation, Mode = mode }, default);
        }

        /// <summary>The body of a proxy (no physics thread; None while its creation is still deferred).</summary>
        public BodyHandle GetBody(ProxyHandle proxy)
        {
            int slot = LiveSlot(proxy, nameof(GetBody));
            if (_threaded) throw new InvalidOperationException("PhysicsBridge.GetBody: the world is owned by the physics thread; use the bridge's methods.");
            return slot < _wBody.Length && _wGeneration[slot] == proxy.Generation ? _wBody[slot] : default;
        }

        /// <summary>Applies a force at the centre of mass before the next step (see <see cref="World.AddForce"/>).</summary>
        public void AddForce(ProxyHandle proxy, Vector3 force, ForceMode mode = ForceMode.Force)
        {
            int slot = LiveSlot(proxy, nameof(AddForce));
            FieldCheck.Force(force, _gEntity[slot]!, "force");
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.AddForce, Slot = slot, Generation = proxy.Generation, Vector = force, ForceMode = mode }, default);
        }

        /// <summary>Applies a force at a world point before the next step.</summary>
        public void AddForceAtPosition(ProxyHandle proxy, Vector3 force, Vector3 worldPoint, ForceMode mode = ForceMode.Force)
        {
            int slot = LiveSlot(proxy, nameof(AddForceAtPosition));
            FieldCheck.Force(force, _gEntity[slot]!, "force");
            FieldCheck.Position(worldPoint, _gEntity[slot]!, "worldPoint");
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.AddForceAtPosition, Slot = slot, Generation = proxy.Generation, Vector = force, Point = worldPoint, ForceMode = mode }, default);
        }

        /// <summary>Applies a torque before the next step.</summary>
        public void AddTorque(ProxyHandle proxy, Vector3 torque, ForceMode mode = ForceMode.Force)
        {
            int slot = LiveSlot(proxy, nameof(AddTorque));
            FieldCheck.Force(torque, _gEntity[slot]!, "torque");
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.AddTorque, Slot = slot, Generation = proxy.Generation, Vector = torque, ForceMode = mode }, default);
        }

        /// <summary>Sets the linear velocity before the next step, m/s.</summary>
        public void SetLinearVelocity(ProxyHandle proxy, Vector3 velocity)
        {
            int slot = LiveSlot(proxy, nameof(SetLinearVelocity));
            FieldCheck.Speed(velocity, _gEntity[slot]!, "linearVelocity");
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.SetLinearVelocity, Slot = slot, Generation = proxy.Generation, Vector = velocity }, default);
        }

        /// <summary>Sets the angular velocity before the next step, rad/s.</summary>
        public void SetAngularVelocity(ProxyHandle proxy, Vector3 velocity)
        {
            int slot = LiveSlot(proxy, nameof(SetAngularVelocity));
            FieldCheck.Speed(velocity, _gEntity[slot]!, "angularVelocity");
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.SetAngularVelocity, Slot = slot, Generation = proxy.Generation, Vector = velocity }, default);
        }

        /// <summary>Moves a body instantly (no velocity, no interpolation across the jump) before the next step.</summary>
        public void Teleport(ProxyHandle proxy, Vector3 position, Quaternion rotation)
        {
            int slot = LiveSlot(proxy, nameof(Teleport));
            FieldCheck.Position(position, _gEntity[slot]!, "position");
            Quaternion q = FieldCheck.Rotation(rotation, _gEntity[slot]!, "rotation");
            _gInput[slot] = new Pose(position, q);
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.Teleport, Slot = slot, Generation = proxy.Generation, Vector = position, Rotation = q }, default);
        }

        /// <summary>Streams this entity's contact forces to <see cref="Haptics"/> (or stops).</summary>
        public void SetHaptics(ProxyHandle proxy, bool enabled)
        {
            int slot = LiveSlot(proxy, nameof(SetHaptics));
            if (Haptics == null) throw new InvalidOperationException("PhysicsBridge.SetHaptics: the haptics stream is off (PhysicsBridgeSettings.HapticsCapacity is 0).");
            Enqueue(new BridgeCommand { Kind = BridgeCommandKind.SetHaptics, Slot = slot, Generation = proxy.Generation, Flag = enabled }, default);
        }

        /// <summary>
        /// Reads the pose of every game-driven entity. Their bodies follow over the next steps
        /// with the velocity that reaches the pose (kinematic targets, spread evenly over the
        /// steps of the frame), so they push what they meet.
        /// </summary>
        public void SyncFromGame()
        {
            ThrowIfDisposed();
            ThrowIfDispatching(nameof(SyncFromGame));
            for (int slot = 0; slot < _gSlots.SlotCount; slot++)
            {
                if (_gState[slot] != Live || _gMode[slot] != DriveMode.Game || _gStatic[slot]) continue;
                IPhysicsEntity e = _gEntity[slot]!;
                e.GetPose(out Vector3 p, out Quaternion q);
                FieldCheck.Position(p, e, "position");
                _gInput[slot] = new Pose(p, FieldCheck.Rotation(q, e, "rotation"));
            }
            if (_threaded) PostInputs();
            else TakeInputs();
        }

        /// <summary>
        /// Advances physics by a frame of <paramref name="frameDt"/> seconds: as many fixed
        /// steps as the accumulator calls for, each followed by its contact events. With a
        /// physics thread it only delivers the events of the steps the thread has taken since
        /// the last call. Returns the number of steps taken (or delivered).
        /// </summary>
        public int Step(float frameDt)
        {
            ThrowIfDisposed();
            FieldCheck.NonNegative(frameDt, "PhysicsBridge.Step", nameof(frameDt));
            ThrowIfDispatching(nameof(Step));
            if (_threaded) return DeliverThreadEvents();
            ApplyCommands(_commands);
            int steps = _stepper.Consume(frameDt);
            for (int k = 0; k < steps; k++)
            {
                StepWorld(_stepper.FixedDt, k, steps);
                Deliver(_wEvents);
                _wEvents.Clear();
                ApplyCommands(_commands);
            }
            return steps;
        }

        /// <summary>
        /// Writes the pose of every physics-driven entity: blended between the last two steps
        /// when <see cref="PhysicsBridgeSettings.Interpolate"/> is on (render one step behind,
        /// never ahead), else the last step's.
        /// </summary>
        public void SyncToGame()
        {
            ThrowIfDisposed();
            ThrowIfDispatching(nameof(SyncToGame));
            if (_threaded) { WriteThreadPoses(); return; }
            float alpha = _settings.Interpolate ? _stepper.InterpolationFactor : 1f;
            for (int slot = 0; slot < _gSlots.SlotCount; slot++)
            {
                if (_gState[slot] != Live || _gMode[slot] != DriveMode.Physics) continue;
                if (slot >= _wBody.Length || _wGeneration[slot] != _gSlots.Generation[slot] || _wBody[slot].IsNone) continue;
                Pose p = _world.GetInterpolatedPose(_wBody[slot], alpha);
                _gEntity[slot]!.SetPose(p.Position, p.Rotation);
            }
        }

        /// <summary>Stops the physics thread (if any) and drops every pending command.</summary>
        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            StopThread();
            // The thread is gone (or never was): an open recording is closed here.
            _gRecording = false;
            DropRecordRequest();
            CloseRecorder();
        }

        bool _disposed;

        void ThrowIfDisposed()
        {
            if (_disposed) throw new ObjectDisposedException(nameof(PhysicsBridge));
            ThrowIfThreadFailed();
        }

        void ThrowIfDispatching(string what)
        {
            if (_dispatching)
                throw new InvalidOperationException($"PhysicsBridge.{what} was called from a contact callback; the bridge cannot sync or step while it delivers events (register, unregister and forces are deferred instead).");
        }

        int LiveSlot(ProxyHandle proxy, string caller)
        {
            ThrowIfDisposed();
            if (!IsRegistered(proxy))
                throw new StaleHandleException(proxy.IsNone
                    ? $"PhysicsBridge.{caller}: the proxy handle is None."
                    : proxy.WorldId != _world.Id
                        ? $"PhysicsBridge.{caller}: {proxy} belongs to the bridge of World {proxy.WorldId}, not this one (World {_world.Id})."
                        : $"PhysicsBridge.{caller}: {proxy} does not name a registered entity (it was unregistered).");
            return proxy.Index;
        }

        int AllocateSlot()
        {
            ReclaimReleasedSlots();
            int slot = _gSlots.Allocate(out bool grew);
            if (grew)
            {
                int n = _gSlots.Capacity;
                Array.Resize(ref _gEntity, n);
                Array.Resize(ref _gState, n);
                Array.Resize(ref _gMode, n);
                Array.Resize(ref _gStatic, n);
                Array.Resize(ref _gInput, n);
            }
            return slot;
        }

        // Commands are applied at once when the game thread owns the world and no events are
        // being delivered; otherwise between steps.
        void Enqueue(in BridgeCommand cmd, ReadOnlySpan<ShapeDef> shapes)
        {
            if (_threaded)
            {
                lock (_sync) AddCommand(_commands, cmd, shapes);
                return;
            }
            AddCommand(_commands, cmd, shapes);
            if (!_dispatching) ApplyCommands(_commands);
        }

        static void AddCommand(BridgeCommandQueue q, in BridgeCommand cmd, ReadOnlySpan<ShapeDef> shapes)
        {
            BridgeCommand c = cmd;
            if (shapes.Length > 0)
            {
                c.ShapeStart = q.AddShapes(shapes);
                c.ShapeCount = shapes.Length;
            }
            q.Add(c);
        }

        // Delivers resolved events to the listener; the game may register, unregister and push
        // forces meanwhile (deferred). Begin and persist events of entities the game removed
        // earlier in the batch are skipped; end events always go out.
        void Deliver(BridgeContactBatch batch)
        {
            _deliveringPoints = batch.Points;
            BridgeContact[] events = batch.Contacts;
            int count = batch.ContactCount;
            if (_listener == null || count == 0) return;
            _dispatching = true;
            try
            {
                for (int k = 0; k < count; k++)
                {
                    ref BridgeContact c = ref events[k];
                    if (c.Kind != ContactEventKind.End && (Removed(c.ProxyA) || Removed(c.ProxyB))) continue;
                    _listener.OnContact(c);
                }
            }
            finally
            {
                _dispatching = false;
                Array.Clear(events, 0, count); // drop entity references
            }
        }

        bool Removed(ProxyHandle p) => !p.IsNone && !IsRegistered(p);

        BridgeContactPoint[] _deliveringPoints = Array.Empty<BridgeContactPoint>();

        /// <summary>
        /// The manifold points of <paramref name="contact"/>; valid only inside
        /// <see cref="IBridgeContactListener.OnContact"/> (the buffer is reused afterwards).
        /// </summary>
        public ReadOnlySpan<BridgeContactPoint> GetPoints(in BridgeContact contact)
        {
            if (!_dispatching) throw new InvalidOperationException("PhysicsBridge.GetPoints is only valid inside a contact callback.");
            return new ReadOnlySpan<BridgeContactPoint>(_deliveringPoints, contact.FirstPoint, contact.StoredPoints);
        }
    }
}
