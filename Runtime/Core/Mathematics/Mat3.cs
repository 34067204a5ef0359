using System;
using System.Numerics;

namespace Fulcrum.Mathematics
{
    /// <summary>
    /// A 3x3 matrix of floats stored as three columns, for inertia tensors, rotations and
    /// deformation gradients. <c>M * v</c> is <c>C0 * v.X + C1 * v.Y + C2 * v.Z</c>.
    /// System.Numerics has no 3x3 type; this one is a blittable 36-byte struct.
    /// </summary>
    public struct Mat3 : IEquatable<Mat3>
    {
        /// <summary>First column.</summary>
        public Vector3 C0;
        /// <summary>Second column.</summary>
        public Vector3 C1;
        /// <summary>Third column.</summary>
        public Vector3 C2;

        /// <summary>Builds a matrix from its three columns.</summary>
        public Mat3(Vector3 c0, Vector3 c1, Vector3 c2)
        {
            C0 = c0;
            C1 = c1;
            C2 = c2;
        }

        /// <summary>The identity matrix.</summary>
        public static Mat3 Identity => new Mat3(Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ);

        /// <summary>The zero matrix.</summary>
        public static Mat3 Zero => default;

        /// <summary>A diagonal matrix with <paramref name="d"/> on the diagonal.</summary>
        public static Mat3 Diagonal(Vector3 d) =>
            new Mat3(new Vector3(d.X, 0, 0), new Vector3(0, d.Y, 0), new Vector3(0, 0, d.Z));

        /// <summary>Builds a matrix from its three rows.</summary>
        public static Mat3 FromRows(Vector3 r0, Vector3 r1, Vector3 r2) =>
            new Mat3(new Vector3(r0.X, r1.X, r2.X), new Vector3(r0.Y, r1.Y, r2.Y), new Vector3(r0.Z, r1.Z, r2.Z));

        /// <summary>The rotation matrix of a unit quaternion.</summary>
        public static Mat3 FromQuaternion(Quaternion q)
        {
            // s = 2 / |q|^2 instead of 2: a float quaternion is unit only to about 1e-7, and
            // the plain formula would scale the axes by |q|^2, which a contact's separation
            // across a 1 m box reads as a 0.1 micrometre error that changes every step.
            float s = 2f / (q.X * q.X + q.Y * q.Y + q.Z * q.Z + q.W * q.W);
            float xx = s * q.X * q.X, yy = s * q.Y * q.Y, zz = s * q.Z * q.Z;
            float xy = s * q.X * q.Y, xz = s * q.X * q.Z, yz = s * q.Y * q.Z;
            float wx = s * q.W * q.X, wy = s * q.W * q.Y, wz = s * q.W * q.Z;
            return new Mat3(
                new Vector3(1 - (yy + zz), xy + wz, xz - wy),
                new Vector3(xy - wz, 1 - (xx + zz), yz + wx),
                new Vector3(xz + wy, yz - wx, 1 - (xx + yy)));
        }

        /// <summary>The cross-product matrix: <c>Skew(a) * b == Vector3.Cross(a, b)</c>.</summary>
        public static Mat3 Skew(Vector3 a) =>
            new Mat3(new Vector3(0, a.Z, -a.Y), new Vector3(-a.Z, 0, a.X), new Vector3(a.Y, -a.X, 0));

        /// <summary>The outer product <c>a b^T</c>.</summary>
        public static Mat3 Outer(Vector3 a, Vector3 b) => new Mat3(a * b.X, a * b.Y, a * b.Z);

        /// <summary>First row.</summary>
        public readonly Vector3 R0 => new Vector3(C0.X, C1.X, C2.X);
        /// <summary>Second row.</summary>
        public readonly Vector3 R1 => new Vector3(C0.Y, C1.Y, C2.Y);
        /// <summary>Third row.</summary>
        public readonly Vector3 R2 => new Vector3(C0.Z, C1.Z, C2.Z);

        /// <summary>The element in row <paramref name="row"/> and column <paramref name="col"/> (0-based).</summary>
        public readonly float this[int row, int col]
        {
            get
            {
                Vector3 c = col == 0 ? C0 : col == 1 ? C1 : col == 2 ? C2 : throw new ArgumentOutOfRangeException(nameof(col));
                return row == 0 ? c.X : row == 1 ? c.Y : row == 2 ? c.Z : throw new ArgumentOutOfRangeException(nameof(row));
            }
        }

        /// <summary>The sum of the diagonal.</summary>
        public readonly float Trace => C0.X + C1.Y + C2.Z;

        /// <summary>The determinant (the signed volume of the three columns).</summary>
        public readonly float Determinant => Vector3.Dot(C0, Vector3.Cross(C1, C2));

        /// <summary>The Frobenius norm squared (the sum of squares of all entries).</summary>
        public readonly float FrobeniusSquared => C0.LengthSquared() + C1.LengthSquared() + C2.LengthSquared();

        /// <summary>The transpose.</summary>
        public readonly Mat3 Transposed => new Mat3(R0, R1, R2);

        /// <summary>The diagonal as a vector.</summary>
        public readonly Vector3 DiagonalVector => new Vector3(C0.X, C1.Y, C2.Z);

        /// <summary>True when every entry is finite.</summary>
        public readonly bool IsFinite => Validate.IsFinite(C0) && Validate.IsFinite(C1) && Validate.IsFinite(C2);

        /// <summary>
        /// The inverse by the adjugate, or <see cref="Zero"/> when the matrix is singular
        /// (|det| below 1e-30 in relative terms): a zero inverse mass/inertia is the safe answer
        /// for the solver, which treats it as an infinitely heavy direction.
        /// </summary>
        public readonly Mat3 Inverse()
        {
            TryInvert(out Mat3 inv);
            return inv;
        }

        /// <summary>Inverts by the adjugate; false (and zero) when the matrix is singular.</summary>
        public readonly bool TryInvert(out Mat3 inverse)
        {
            // Rows of the inverse are the cross products of columns divided by the determinant.
            Vector3 r0 = Vector3.Cross(C1, C2);
            Vector3 r1 = Vector3.Cross(C2, C0);
            Vector3 r2 = Vector3.Cross(C0, C1);
            float det = Vector3.Dot(C0, r0);
            float scale = MathF.Max(FrobeniusSquared, 1e-30f);
            if (!(MathF.Abs(det) > 1e-30f * scale * MathF.Sqrt(scale)) || !float.IsFinite(det))
            {
                inverse = Zero;
                return false;
            }
            float invDet = 1f / det;
            inverse = FromRows(r0 * invDet, r1 * invDet, r2 * invDet);
            return true;
        }

        /// <summary>Matrix times column vector.</summary>
        public static Vector3 operator *(in Mat3 m, Vector3 v) => m.C0 * v.X + m.C1 * v.Y + m.C2 * v.Z;

        /// <summary>Matrix product.</summary>
        public static Mat3 operator *(in Mat3 a, in Mat3 b) => new Mat3(a * b.C0, a * b.C1, a * b.C2);

        /// <summary>Scales every entry.</summary>
        public static Mat3 operator *(in Mat3 m, float s) => new Mat3(m.C0 * s, m.C1 * s, m.C2 * s);

        /// <summary>Scales every entry.</summary>
        public static Mat3 operator *(float s, in Mat3 m) => m * s;

        /// <summary>Entry-wise sum.</summary>
        public static Mat3 operator +(in Mat3 a, in Mat3 b) => new Mat3(a.C0 + b.C0, a.C1 + b.C1, a.C2 + b.C2);

        /// <summary>Entry-wise difference.</summary>
        public static Mat3 operator -(in Mat3 a, in Mat3 b) => new Mat3(a.C0 - b.C0, a.C1 - b.C1, a.C2 - b.C2);

        /// <summary>Transpose(this) * v without forming the transpose.</summary>
        public readonly Vector3 TransposeMultiply(Vector3 v) =>
            new Vector3(Vector3.Dot(C0, v), Vector3.Dot(C1, v), Vector3.Dot(C2, v));

        /// <summary>R * diag(d) * R^T, the usual way to take a principal-axis tensor to another frame.</summary>
        public static Mat3 RotateDiagonal(in Mat3 r, Vector3 d)
        {
            Mat3 rd = new Mat3(r.C0 * d.X, r.C1 * d.Y, r.C2 * d.Z);
            return rd * r.Transposed;
        }

        /// <summary>The double-contraction A:B = sum of A_ij B_ij.</summary>
        public static float DoubleDot(in Mat3 a, in Mat3 b) =>
            Vector3.Dot(a.C0, b.C0) + Vector3.Dot(a.C1, b.C1) + Vector3.Dot(a.C2, b.C2);

        /// <inheritdoc/>
        public readonly bool Equals(Mat3 other) => C0 == other.C0 && C1 == other.C1 && C2 == other.C2;

        /// <inheritdoc/>
        public override readonly bool Equals(object? obj) => obj is Mat3 m && Equals(m);

        /// <inheritdoc/>
        public override readonly int GetHashCode() => HashCode.Combine(C0, C1, C2);

        /// <summary>Exact equality of every entry.</summary>
        public static bool operator ==(Mat3 a, Mat3 b) => a.Equals(b);

        /// <summary>Inequality of any entry.</summary>
        public static bool operator !=(Mat3 a, Mat3 b) => !a.Equals(b);

        /// <inheritdoc/>
        public override readonly string ToString() => $"[{R0}; {R1}; {R2}]";
    }
}
