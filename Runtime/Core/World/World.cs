using System;
using System.Numerics;

namespace Fulcrum
{
    /// <summary>
    /// The physics world: owns bodies, shapes, joints and (through <see cref="SoftBodyStage"/>)
    /// soft bodies, and advances them with <see cref="Step"/>. Not thread-safe: call it from
    /// one thread, and never from inside a step (callbacks get a read-only view).
    /// </summary>
    public sealed partial class World
    {
        internal BodyStorage Bodies = new BodyStorage();
        internal ShapeStorage Shapes = new ShapeStorage();

        static int s_lastId;

        WorldSettings _settings;

        /// <summary>
        /// This world's id, unique in the process (from 1), carried by every handle it issues so
        /// that a handle of another world is refused instead of reaching the object in the same
        /// slot here. Not simulation state: saving and restoring a world does not carry it.
        /// </summary>
        public int Id { get; } = System.Threading.Interlocked.Increment(ref s_lastId);

        /// <summary>
        /// The slot that <paramref name="handle"/> (a <paramref name="type"/> naming a
        /// <paramref name="noun"/>) holds in <paramref name="slots"/>, or the one-line
        /// <see cref="StaleHandleException"/> that every call taking a handle throws: for a handle
        /// of another world (or built with no world id), for none, and for a slot that was
        /// <paramref name="ended"/>. The text is built only when it throws (no allocation).
        /// </summary>
        internal int LiveSlot(in HandleId handle, SlotAllocator slots, string type, string noun, string ended)
        {
            if (!handle.IsNone && handle.WorldId != Id)
                throw new StaleHandleException(handle.WorldId == 0
                    ? $"{handle.Format(type)} carries no world id: use handles returned by World {Id}'s own calls."
                    : $"{handle.Format(type)} belongs to World {handle.WorldId}, not to this World {Id}: handles cannot cross worlds.");
            if (!slots.IsLive(handle.Index, handle.Generation))
                throw new StaleHandleException(handle.IsNone
                    ? $"The {noun} handle is None."
                    : $"{handle.Format(type)} does not name a live {noun}: it was {ended}, or was never issued by this world.");
            return handle.Index;
        }
        bool _inStep;
        long _stepIndex;
        StepProfile _profile;

        /// <summary>Creates an empty world with <see cref="WorldSettings.Default"/>.</summary>
        public World() : this(WorldSettings.Default) { }

        /// <summary>Creates an empty world; throws if a setting is invalid.</summary>
        public World(WorldSettings settings)
        {
            settings.Validate();
            _settings = settings;
        }

        /// <summary>The settings; assigning validates them first (a bad value changes nothing).</summary>
        public WorldSettings Settings
        {
            get => _settings;
            set
            {
                ThrowIfInStep();
                value.Validate();
                _settings = value;
            }
        }

        /// <summary>Gravity, m/s^2 (a shortcut into <see cref="Settings"/>).</summary>
        public Vector3 Gravity
        {
            get => _settings.Gravity;
            set
            {
                ThrowIfInStep();
                Mathematics.Validate.Finite(value, nameof(Gravity));
                _settings.Gravity = value;
            }
        }

        /// <summary>Live bodies.</summary>
        public int BodyCount => Bodies.ActiveCount;

        /// <summary>Live shapes.</summary>
        public int ShapeCount => Shapes.ActiveCount;

        /// <summary>Steps taken since the world was created.</summary>
        public long StepIndex => _stepIndex;

        /// <summary>Simulated time, seconds (the sum of every step's dt).</summary>
        public double Time { get; private set; }

        /// <summary>Per-stage timings of the last step.</summary>
        public StepProfile LastStepProfile => _profile;

        /// <summary>True while <see cref="Step"/> runs (callbacks may check it).</summary>
        public bool IsStepping => _inStep;

        /// <summary>
        /// The soft-body stage, installed by Fulcrum.SoftBodies when the first soft body is
        /// created. Null in a world without soft bodies, whose step then skips the stage.
        /// </summary>
        public ISoftBodyStage? SoftBodyStage { get; set; }

        void ThrowIfInStep()
        {
            if (_inStep)
                throw new InvalidOperationException("The world cannot be changed during Step (from a callback); defer the change until Step returns.");
        }
    }
}
