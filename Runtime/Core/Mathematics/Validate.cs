using System;
using System.Numerics;

namespace Fulcrum.Mathematics
{
    /// <summary>
    /// Checks on user input made before anything is changed, so that a bad value is
    /// rejected with the name of the field and the world is left exactly as it was.
    /// </summary>
    public static class Validate
    {
        /// <summary>True when the value is neither NaN nor infinite.</summary>
        public static bool IsFinite(float v) => float.IsFinite(v);

        /// <summary>True when every component is finite.</summary>
        public static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

        /// <summary>True when every component is finite.</summary>
        public static bool IsFinite(Quaternion q) =>
            float.IsFinite(q.X) && float.IsFinite(q.Y) && float.IsFinite(q.Z) && float.IsFinite(q.W);

        /// <summary>Throws when <paramref name="v"/> is NaN or infinite.</summary>
        public static void Finite(float v, string name)
        {
            if (!float.IsFinite(v)) throw new ArgumentException($"{name} must be finite, got {v}.", name);
        }

        /// <summary>Throws when any component of <paramref name="v"/> is NaN or infinite.</summary>
        public static void Finite(Vector3 v, string name)
        {
            if (!IsFinite(v)) throw new ArgumentException($"{name} must be finite, got {v}.", name);
        }

        /// <summary>Throws when <paramref name="v"/> is not finite and &gt; 0.</summary>
        public static void Positive(float v, string name)
        {
            if (!(float.IsFinite(v) && v > 0)) throw new ArgumentException($"{name} must be finite and > 0, got {v}.", name);
        }

        /// <summary>Throws when <paramref name="v"/> is not finite and &gt;= 0.</summary>
        public static void NonNegative(float v, string name)
        {
            if (!(float.IsFinite(v) && v >= 0)) throw new ArgumentException($"{name} must be finite and >= 0, got {v}.", name);
        }

        /// <summary>Throws when any component is not finite and &gt; 0.</summary>
        public static void Positive(Vector3 v, string name)
        {
            if (!(IsFinite(v) && v.X > 0 && v.Y > 0 && v.Z > 0))
                throw new ArgumentException($"{name} must be finite and > 0 on every axis, got {v}.", name);
        }

        /// <summary>
        /// Throws when the quaternion is not finite or too short to normalise; returns it
        /// normalised, so that a slightly unnormalised rotation from user code is accepted.
        /// </summary>
        public static Quaternion Rotation(Quaternion q, string name)
        {
            if (!IsFinite(q)) throw new ArgumentException($"{name} must be finite, got {q}.", name);
            float lenF = q.Length();
            if (lenF > 1e-6f && float.IsFinite(lenF)) return Quaternion.Multiply(q, 1f / lenF);
            // In double: the float length of a quaternion of 1e20s overflows to infinity and
            // would normalise it to zero.
            double len = Math.Sqrt((double)q.X * q.X + (double)q.Y * q.Y + (double)q.Z * q.Z + (double)q.W * q.W);
            if (!(len > 1e-6)) throw new ArgumentException($"{name} must be a non-zero quaternion, got {q}.", name);
            return new Quaternion((float)(q.X / len), (float)(q.Y / len), (float)(q.Z / len), (float)(q.W / len));
        }
    }
}
