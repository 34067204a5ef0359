using System;
using System.Numerics;

namespace Fulcrum
{
    /// <summary>
    /// The documented ranges of user input. Values outside them are refused up front with the
    /// field named (the world is left unchanged), because each one overflows single precision
    /// somewhere downstream (a product of two of them, a square, a normalisation) and would
    /// otherwise turn bodies NaN steps later, far from the call that caused it. Speeds inside
    /// the input range but above <see cref="WorldSettings.MaxLinearSpeed"/> are clamped to that
    /// cap by the integrator (see <see cref="WorldSettings.MaxLinearSpeed"/>). Scene files are
    /// checked against the same numbers.
    /// </summary>
    public static class Limits
    {
        /// <summary>
        /// Largest coordinate of a body position, kinematic target, joint anchor or force point, m
        /// (each axis). Float spacing there is 8 mm, the coarsest that still resolves a
        /// default 5 mm slop. Default world bounds for teleports and creation: +-1e5 m.
        /// </summary>
        public const float MaxPosition = 1e5f;

        /// <summary>Largest size of a shape (radius, half extent, half height, hull or mesh coordinate, compound offset), m.</summary>
        public const float MaxShapeSize = 1e5f;

        /// <summary>
        /// Smallest size of a sphere or capsule radius or a box half extent, m (0.1 mm): below it
        /// the mass and inertia formulas (r^5) underflow to zero or denormals.
        /// </summary>
        public const float MinShapeSize = 1e-4f;

        /// <summary>Smallest mass of a dynamic body (given or from its shapes), kg: below it 1/m overflows the solver's products.</summary>
        public const float MinMass = 1e-6f;

        /// <summary>Largest mass of a dynamic body (given or from its shapes), kg.</summary>
        public const float MaxMass = 1e12f;

        /// <summary>Largest magnitude of a force (N) or torque (N m) passed to AddForce/AddTorque, and of the sum accumulated for one step.</summary>
        public const float MaxForce = 1e20f;

        /// <summary>
        /// Largest magnitude of a linear (m/s) or angular (rad/s) velocity given as input. Inside
        /// it, linear speed is clamped to <see cref="WorldSettings.MaxLinearSpeed"/> and angular
        /// speed to <see cref="MaxAngularSpeed"/> and to the spin at which the body's farthest
        /// point moves at MaxLinearSpeed (see <see cref="WorldSettings.MaxLinearSpeed"/>).
        /// </summary>
        public const float MaxInputSpeed = 1e6f;

        /// <summary>Hard cap on any body's angular speed, rad/s (about 95,000 rpm), whatever its size.</summary>
        public const float MaxAngularSpeed = 1e4f;

        /// <summary>Largest magnitude of a body's gravity scale.</summary>
        public const float MaxGravityScale = 1e6f;

        /// <summary>Largest magnitude of world gravity, m/s^2.</summary>
        public const float MaxGravity = 1e6f;

        /// <summary>Longest time step <see cref="World.Step"/> takes, s.</summary>
        public const float MaxTimeStep = 1f;

        /// <summary>Shortest time step <see cref="World.Step"/> takes, s (one microsecond: below it 1/dt^2 terms overflow).</summary>
        public const float MinTimeStep = 1e-6f;

        /// <summary>Most substeps per step (<see cref="WorldSettings.Substeps"/>).</summary>
        public const int MaxSubsteps = 256;

        /// <summary>Most velocity, position or relax iterations (<see cref="WorldSettings.Iterations"/> and friends).</summary>
        public const int MaxIterations = 1024;

        /// <summary>Most worker threads (<see cref="WorldSettings.Threads"/>).</summary>
        public const int MaxThreads = 64;

        /// <summary>Largest count <see cref="World.Reserve"/> takes (bodies or contact pairs): 2^24, so that the buffers it sizes stay within 32-bit array lengths.</summary>
        public const int MaxReserve = 1 << 24;

        /// <summary>Most points given to a convex hull (API and scene files); the hull keeps at most its own vertex cap of them.</summary>
        public const int MaxHullPoints = 10000;

        // |v| without overflow: in double, so 3e38 on every axis still gives a finite answer.
        internal static double Length(Vector3 v) => Math.Sqrt((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);

        internal static void CheckPosition(Vector3 p, string name)
        {
            Mathematics.Validate.Finite(p, name);
            if (Math.Abs(p.X) > MaxPosition || Math.Abs(p.Y) > MaxPosition || Math.Abs(p.Z) > MaxPosition)
                throw new ArgumentException($"{name} must lie within +-{MaxPosition:G} m on every axis (Limits.MaxPosition), got {p}.", name);
        }

        internal static void CheckSpeed(Vector3 v, string name)
        {
            Mathematics.Validate.Finite(v, name);
            if (Length(v) > MaxInputSpeed)
                throw new ArgumentException($"{name} must have magnitude at most {MaxInputSpeed:G} (Limits.MaxInputSpeed), got {v}.", name);
        }

        internal static void CheckForce(Vector3 f, string name)
        {
            Mathematics.Validate.Finite(f, name);
            if (Length(f) > MaxForce)
                throw new ArgumentException($"{name} must have magnitude at most {MaxForce:G} (Limits.MaxForce), got {f}.", name);
        }

        internal static void CheckGravityScale(float s, string name)
        {
            if (!(float.IsFinite(s) && Math.Abs(s) <= MaxGravityScale))
                throw new ArgumentException($"{name} must be finite and within +-{MaxGravityScale:G} (Limits.MaxGravityScale), got {s}.", name);
        }

        internal static void CheckMass(float m, string name)
        {
            if (!(float.IsFinite(m) && m >= MinMass && m <= MaxMass))
                throw new ArgumentException($"{name} must be between {MinMass:G} and {MaxMass:G} kg (Limits.MinMass/MaxMass), got {m}.", name);
        }
    }
}
