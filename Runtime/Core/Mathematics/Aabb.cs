using System;
using System.Numerics;

namespace Fulcrum.Mathematics
{
    /// <summary>An axis-aligned bounding box given by its corners.</summary>
    public struct Aabb : IEquatable<Aabb>
    {
        /// <summary>Lower corner.</summary>
        public Vector3 Min;
        /// <summary>Upper corner.</summary>
        public Vector3 Max;

        /// <summary>Builds a box from its corners.</summary>
        public Aabb(Vector3 min, Vector3 max)
        {
            Min = min;
            Max = max;
        }

        /// <summary>The tightest box around the triangle (a, b, c).</summary>
        public static Aabb OfTriangle(Vector3 a, Vector3 b, Vector3 c) =>
            new Aabb(Vector3.Min(a, Vector3.Min(b, c)), Vector3.Max(a, Vector3.Max(b, c)));

        /// <summary>A box around <paramref name="center"/> with half-size <paramref name="extents"/>.</summary>
        public static Aabb FromCenterExtents(Vector3 center, Vector3 extents) => new Aabb(center - extents, center + extents);

        /// <summary>An inverted box that any union replaces: the identity of <see cref="Union(in Aabb, in Aabb)"/>.</summary>
        public static Aabb Empty => new Aabb(new Vector3(float.MaxValue), new Vector3(-float.MaxValue));

        /// <summary>The centre.</summary>
        public readonly Vector3 Center => 0.5f * (Min + Max);

        /// <summary>Half the size on each axis.</summary>
        public readonly Vector3 Extents => 0.5f * (Max - Min);

        /// <summary>The size on each axis.</summary>
        public readonly Vector3 Size => Max - Min;

        /// <summary>True when Min &lt;= Max on every axis.</summary>
        public readonly bool IsValid => Min.X <= Max.X && Min.Y <= Max.Y && Min.Z <= Max.Z;

        /// <summary>The surface area; the cost measure of the surface area heuristic (SAH).</summary>
        public readonly float SurfaceArea
        {
            get
            {
                Vector3 d = Max - Min;
                return 2f * (d.X * d.Y + d.Y * d.Z + d.Z * d.X);
            }
        }

        /// <summary>The smallest box holding both.</summary>
        public static Aabb Union(in Aabb a, in Aabb b) => new Aabb(Vector3.Min(a.Min, b.Min), Vector3.Max(a.Max, b.Max));

        /// <summary>The smallest box holding the box and a point.</summary>
        public static Aabb Union(in Aabb a, Vector3 p) => new Aabb(Vector3.Min(a.Min, p), Vector3.Max(a.Max, p));

        /// <summary>True when the boxes overlap or touch.</summary>
        public readonly bool Overlaps(in Aabb other) =>
            Min.X <= other.Max.X && Max.X >= other.Min.X &&
            Min.Y <= other.Max.Y && Max.Y >= other.Min.Y &&
            Min.Z <= other.Max.Z && Max.Z >= other.Min.Z;

        /// <summary>True when <paramref name="inner"/> lies inside this box.</summary>
        public readonly bool Contains(in Aabb inner) =>
            Min.X <= inner.Min.X && Min.Y <= inner.Min.Y && Min.Z <= inner.Min.Z &&
            Max.X >= inner.Max.X && Max.Y >= inner.Max.Y && Max.Z >= inner.Max.Z;

        /// <summary>True when the point lies inside or on the box.</summary>
        public readonly bool Contains(Vector3 p) =>
            p.X >= Min.X && p.Y >= Min.Y && p.Z >= Min.Z && p.X <= Max.X && p.Y <= Max.Y && p.Z <= Max.Z;

        /// <summary>The box grown by <paramref name="margin"/> on every side.</summary>
        public readonly Aabb Expanded(float margin) => new Aabb(Min - new Vector3(margin), Max + new Vector3(margin));

        /// <summary>
        /// The world box of a local box (centre <paramref name="localCenter"/>, half-size
        /// <paramref name="localExtents"/>) under a pose: |R| * extents (Arvo 1990).
        /// </summary>
        public static Aabb Transform(in Pose pose, Vector3 localCenter, Vector3 localExtents)
        {
            Mat3 r = Mat3.FromQuaternion(pose.Rotation);
            Vector3 c = pose.TransformPoint(localCenter);
            Vector3 e = Vector3.Abs(r.C0) * localExtents.X + Vector3.Abs(r.C1) * localExtents.Y + Vector3.Abs(r.C2) * localExtents.Z;
            return new Aabb(c - e, c + e);
        }

        /// <inheritdoc/>
        public readonly bool Equals(Aabb other) => Min == other.Min && Max == other.Max;

        /// <inheritdoc/>
        public override readonly bool Equals(object? obj) => obj is Aabb a && Equals(a);

        /// <inheritdoc/>
        public override readonly int GetHashCode() => HashCode.Combine(Min, Max);

        /// <summary>Exact equality.</summary>
        public static bool operator ==(Aabb a, Aabb b) => a.Equals(b);

        /// <summary>Inequality.</summary>
        public static bool operator !=(Aabb a, Aabb b) => !a.Equals(b);

        /// <inheritdoc/>
        public override readonly string ToString() => $"[{Min} .. {Max}]";
    }
}
