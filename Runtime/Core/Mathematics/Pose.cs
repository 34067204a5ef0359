using System;
using System.Numerics;

namespace Fulcrum.Mathematics
{
    /// <summary>
    /// A rigid transform: rotate by <see cref="Rotation"/>, then translate by
    /// <see cref="Position"/>. Maps a body's local frame to the world frame.
    /// </summary>
    public struct Pose : IEquatable<Pose>
    {
        /// <summary>Translation, metres.</summary>
        public Vector3 Position;
        /// <summary>Rotation, a unit quaternion.</summary>
        public Quaternion Rotation;

        /// <summary>Builds a pose from a position and a rotation.</summary>
        public Pose(Vector3 position, Quaternion rotation)
        {
            Position = position;
            Rotation = rotation;
        }

        /// <summary>The identity pose.</summary>
        public static Pose Identity => new Pose(Vector3.Zero, Quaternion.Identity);

        /// <summary>Maps a point from the local frame to the world frame.</summary>
        public readonly Vector3 TransformPoint(Vector3 local) => Position + Vector3.Transform(local, Rotation);

        /// <summary>Rotates a direction from the local frame to the world frame.</summary>
        public readonly Vector3 TransformDirection(Vector3 local) => Vector3.Transform(local, Rotation);

        /// <summary>Maps a world point into the local frame.</summary>
        public readonly Vector3 InverseTransformPoint(Vector3 world) =>
            Vector3.Transform(world - Position, Quaternion.Conjugate(Rotation));

        /// <summary>Rotates a world direction into the local frame.</summary>
        public readonly Vector3 InverseTransformDirection(Vector3 world) =>
            Vector3.Transform(world, Quaternion.Conjugate(Rotation));

        /// <summary>The inverse transform.</summary>
        public readonly Pose Inverse()
        {
            Quaternion inv = Quaternion.Conjugate(Rotation);
            return new Pose(Vector3.Transform(-Position, inv), inv);
        }

        /// <summary>Composition: <c>(a * b).TransformPoint(p) == a.TransformPoint(b.TransformPoint(p))</c>.</summary>
        public static Pose operator *(in Pose a, in Pose b) =>
            new Pose(a.TransformPoint(b.Position), Quaternion.Normalize(a.Rotation * b.Rotation));

        /// <inheritdoc/>
        public readonly bool Equals(Pose other) => Position == other.Position && Rotation == other.Rotation;

        /// <inheritdoc/>
        public override readonly bool Equals(object? obj) => obj is Pose p && Equals(p);

        /// <inheritdoc/>
        public override readonly int GetHashCode() => HashCode.Combine(Position, Rotation);

        /// <summary>Exact equality.</summary>
        public static bool operator ==(Pose a, Pose b) => a.Equals(b);

        /// <summary>Inequality.</summary>
        public static bool operator !=(Pose a, Pose b) => !a.Equals(b);

        /// <inheritdoc/>
        public override readonly string ToString() => $"({Position}, {Rotation})";
    }
}
