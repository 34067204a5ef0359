using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// Input checks that name the component (or entity) and the field, and build their message
    /// only when the check fails: the checks run on every AddForce and transform write, which
    /// must not allocate.
    /// </summary>
    internal static class FieldCheck
    {
        /// <summary>Throws "owner: field must be finite" unless every component of <paramref name="v"/> is finite.</summary>
        public static void Finite(Vector3 v, object owner, string field)
        {
            if (!Validate.IsFinite(v)) throw new ArgumentException($"{owner}: {field} must be finite, got {v}.", field);
        }

        /// <summary>Throws unless <paramref name="v"/> is finite and within <see cref="Limits.MaxPosition"/> on every axis.</summary>
        public static void Position(Vector3 v, object owner, string field)
        {
            Finite(v, owner, field);
            float m = Limits.MaxPosition;
            if (Math.Abs(v.X) > m || Math.Abs(v.Y) > m || Math.Abs(v.Z) > m)
                throw new ArgumentException($"{owner}: {field} must lie within +-{m:G} m on every axis (Limits.MaxPosition), got {v}.", field);
        }

        /// <summary>Throws unless <paramref name="v"/> is finite with magnitude at most <see cref="Limits.MaxForce"/>.</summary>
        public static void Force(Vector3 v, object owner, string field)
        {
            Finite(v, owner, field);
            if (Limits.Length(v) > Limits.MaxForce)
                throw new ArgumentException($"{owner}: {field} must have magnitude at most {Limits.MaxForce:G} (Limits.MaxForce), got {v}.", field);
        }

        /// <summary>Throws unless <paramref name="v"/> is finite with magnitude at most <see cref="Limits.MaxInputSpeed"/>.</summary>
        public static void Speed(Vector3 v, object owner, string field)
        {
            Finite(v, owner, field);
            if (Limits.Length(v) > Limits.MaxInputSpeed)
                throw new ArgumentException($"{owner}: {field} must have magnitude at most {Limits.MaxInputSpeed:G} (Limits.MaxInputSpeed), got {v}.", field);
        }

        /// <summary>Throws unless <paramref name="v"/> is a mass in [<see cref="Limits.MinMass"/>, <see cref="Limits.MaxMass"/>].</summary>
        public static void Mass(float v, object owner, string field)
        {
            if (!(float.IsFinite(v) && v >= Limits.MinMass && v <= Limits.MaxMass))
                throw new ArgumentException($"{owner}: {field} must be between {Limits.MinMass:G} and {Limits.MaxMass:G} kg (Limits.MinMass/MaxMass), got {v}.", field);
        }

        /// <summary>Throws unless <paramref name="v"/> is a size in [<see cref="Limits.MinShapeSize"/>, <see cref="Limits.MaxShapeSize"/>] m.</summary>
        public static void Size(float v, object owner, string field)
        {
            if (!(float.IsFinite(v) && v >= Limits.MinShapeSize && v <= Limits.MaxShapeSize))
                throw new ArgumentException($"{owner}: {field} must be between {Limits.MinShapeSize:G} and {Limits.MaxShapeSize:G} m (Limits.MinShapeSize/MaxShapeSize), got {v}.", field);
        }

        /// <summary>Throws unless <paramref name="v"/> is finite and &gt; 0.</summary>
        public static void Positive(float v, object owner, string field)
        {
            if (!(float.IsFinite(v) && v > 0)) throw new ArgumentException($"{owner}: {field} must be finite and > 0, got {v}.", field);
        }

        /// <summary>Throws unless <paramref name="v"/> is a joint's breaking force or torque: &gt; 0, infinity for unbreakable.</summary>
        public static void BreakLimit(float v, object owner, string field)
        {
            if (!(v > 0) || float.IsNaN(v)) throw new ArgumentException($"{owner}: {field} must be > 0 (infinity for unbreakable), got {v}.", field);
        }

        /// <summary>Throws unless <paramref name="v"/> is finite and &gt;= 0.</summary>
        public static void NonNegative(float v, object owner, string field)
        {
            if (!(float.IsFinite(v) && v >= 0)) throw new ArgumentException($"{owner}: {field} must be finite and >= 0, got {v}.", field);
        }

        /// <summary>Returns <paramref name="q"/> normalised, or throws "owner: field must be a finite non-zero quaternion".</summary>
        public static Quaternion Rotation(Quaternion q, object owner, string field)
        {
            if (Validate.IsFinite(q))
            {
                float length = q.Length();
                if (length > 1e-6f) return Quaternion.Multiply(q, 1f / length);
            }
            throw new ArgumentException($"{owner}: {field} must be a finite non-zero quaternion, got {q}.", field);
        }
    }
}
