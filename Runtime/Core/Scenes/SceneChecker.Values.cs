using System;
using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// The value rules every field uses, each naming the JSON path and, for a cap, the
    /// Limits constant it comes from.
    /// </summary>
    internal sealed partial class SceneChecker
    {
        bool Finite(float v, string path)
        {
            if (float.IsFinite(v)) return true;
            Error(path, $"must be finite, got {F(v)}");
            return false;
        }

        bool Finite(Vector3 v, string path)
        {
            if (Mathematics.Validate.IsFinite(v)) return true;
            Error(path, $"must be finite, got {V(v)}");
            return false;
        }

        // The API's limits (see Limits), so that a scene the validator passes builds without an ArgumentException.
        void Coordinate(Vector3 v, string path) => Bounded(v, Limits.MaxPosition, path, "Limits.MaxPosition");

        void Extent(Vector3 v, string path) => Bounded(v, Limits.MaxShapeSize, path, "Limits.MaxShapeSize");

        void Bounded(Vector3 v, float max, string path, string limit)
        {
            if (!Finite(v, path)) return;
            if (System.Math.Abs(v.X) > max || System.Math.Abs(v.Y) > max || System.Math.Abs(v.Z) > max)
                Error(path, $"must be within +-{F(max)} on every axis ({limit}), got {V(v)}");
        }

        void Speed(Vector3 v, string path)
        {
            if (Finite(v, path) && Limits.Length(v) > Limits.MaxInputSpeed)
                Error(path, $"must have magnitude at most {F(Limits.MaxInputSpeed)} (Limits.MaxInputSpeed), got {V(v)}");
        }

        void Size(float v, string path)
        {
            if (Positive(v, path) && (v > Limits.MaxShapeSize || v < Limits.MinShapeSize))
                Error(path, $"must be in [{F(Limits.MinShapeSize)}, {F(Limits.MaxShapeSize)}] m (Limits.MinShapeSize/MaxShapeSize), got {F(v)}");
        }

        void Size(Vector3 v, string path)
        {
            Positive(v, path);
            if (Mathematics.Validate.IsFinite(v) && v.X > 0 && v.Y > 0 && v.Z > 0
                && (System.Math.Max(v.X, System.Math.Max(v.Y, v.Z)) > Limits.MaxShapeSize || System.Math.Min(v.X, System.Math.Min(v.Y, v.Z)) < Limits.MinShapeSize))
                Error(path, $"must be in [{F(Limits.MinShapeSize)}, {F(Limits.MaxShapeSize)}] m on every axis (Limits.MinShapeSize/MaxShapeSize), got {V(v)}");
        }

        bool Positive(float v, string path)
        {
            if (float.IsFinite(v) && v > 0) return true;
            Error(path, $"must be > 0, got {F(v)}");
            return false;
        }

        void Positive(Vector3 v, string path)
        {
            if (Mathematics.Validate.IsFinite(v) && v.X > 0 && v.Y > 0 && v.Z > 0) return;
            Error(path, $"must be > 0 on every axis, got {V(v)}");
        }

        bool NonNegative(float v, string path)
        {
            if (float.IsFinite(v) && v >= 0) return true;
            Error(path, $"must be >= 0, got {F(v)}");
            return false;
        }

        // A value already known finite (and of the right sign) against a documented limit.
        void Upto(float v, float lo, float hi, string path, string limit)
        {
            if (v >= lo && v <= hi) return;
            Error(path, $"must be in [{F(lo)}, {F(hi)}] ({limit}), got {F(v)}");
        }

        void InRange(float v, float lo, float hi, string path)
        {
            if (float.IsFinite(v) && v >= lo && v <= hi) return;
            Error(path, $"must be in [{F(lo)}, {F(hi)}], got {F(v)}");
        }

        bool AtLeast(int v, int min, string path)
        {
            if (v >= min) return true;
            Error(path, $"must be >= {min}, got {v}");
            return false;
        }

        void IntInRange(int v, int lo, int hi, string path)
        {
            if (v < lo || v > hi) Error(path, $"must be in [{lo}, {hi}], got {v}");
        }

        void Axis(Vector3 v, string path)
        {
            if (Finite(v, path) && !(v.Length() > 1e-6f)) Error(path, "must be a non-zero direction");
        }

        void Rotation(Quaternion q, string path)
        {
            if (!Mathematics.Validate.IsFinite(q)) Error(path, "must be finite");
            else if (!(q.Length() > 1e-6f)) Error(path, "must be a non-zero quaternion [x, y, z, w]");
        }
    }
}
