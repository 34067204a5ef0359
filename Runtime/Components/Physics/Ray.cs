using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>A ray: an origin and a unit direction (Unity's Ray; the direction is normalised on construction).</summary>
    public readonly struct Ray
    {
        /// <summary>Where the ray starts, world, metres.</summary>
        public readonly Vector3 origin;
        /// <summary>The unit direction.</summary>
        public readonly Vector3 direction;

        /// <summary>A ray from <paramref name="origin"/> along <paramref name="direction"/> (any non-zero length).</summary>
        public Ray(Vector3 origin, Vector3 direction)
        {
            if (!Validate.IsFinite(origin)) throw new ArgumentException($"Ray: origin must be finite, got {origin}.", nameof(origin));
            float length = direction.Length();
            if (!(length > 1e-12f) || !float.IsFinite(length)) throw new ArgumentException($"Ray: direction must be finite and non-zero, got {direction}.", nameof(direction));
            this.origin = origin;
            this.direction = direction / length;
        }

        /// <summary>The point <paramref name="distance"/> metres along the ray.</summary>
        public Vector3 GetPoint(float distance) => origin + direction * distance;

        /// <inheritdoc/>
        public override string ToString() => $"Ray(origin {origin}, direction {direction})";
    }
}
