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
        internal readonly BodyStorage Bodies = new BodyStorage();
        internal readonly ShapeStorage Shapes = new ShapeStorage();

        WorldSettings _settings;
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
