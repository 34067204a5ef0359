using System;
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Two angular rows that keep a hinge axis a1 (fixed in A) parallel to a2 (fixed in B):
    /// with b2, c2 the two axes of B's joint frame perpendicular to a2, C = (a1.b2, a1.c2) = 0.
    /// Differentiating, d(a1.b2)/dt = (b2 x a1).(wB - wA), so the rows are u1 = b2 x a1 and
    /// u2 = c2 x a1, solved together through the 2x2 K_ij = u_i.(IA^-1 + IB^-1) u_j
    /// (Jolt's HingeRotationConstraintPart works the same way).
    /// </summary>
    internal struct HingeRotationPart
    {
        /// <summary>K^-1 entries (symmetric).</summary>
        public float M11, M12, M22;
        /// <summary>Accumulated impulses along u1 and u2, N m s.</summary>
        public float Impulse1, Impulse2;

        const float IllConditioned = 1e-3f;

        /// <summary>Builds K^-1 for the rows <paramref name="u1"/>, <paramref name="u2"/>.</summary>
        public void ComputeMass(in SolverBody a, in SolverBody b, Vector3 u1, Vector3 u2)
        {
            Vector3 iu1 = a.InverseInertia * u1 + b.InverseInertia * u1;
            Vector3 iu2 = a.InverseInertia * u2 + b.InverseInertia * u2;
            float k11 = Vector3.Dot(u1, iu1), k12 = Vector3.Dot(u1, iu2), k22 = Vector3.Dot(u2, iu2);
            float scale = k11 + k22;
            if (!(scale > 0) || !float.IsFinite(scale))
            {
                M11 = M12 = M22 = 0;
                return;
            }
            // Near a 90 degree misalignment (a1 along b2 or c2) one row's direction shrinks to
            // nothing while its error is largest: its plain inverse mass 1/k grows as 1/|u|^2
            // and one step spun the bodies at 1e5-1e6 rad/s. Below a condition of 1e3 the matrix
            // is regularised (K + delta I, delta = 1e-3 trace), which bounds the impulse the
            // vanishing row can ask for; a well-aligned hinge (|u1| = |u2| = 1) is untouched.
            float det = k11 * k22 - k12 * k12;
            if (!(det > IllConditioned * k11 * k22) || k11 < IllConditioned * scale || k22 < IllConditioned * scale)
            {
                float delta = IllConditioned * scale;
                k11 += delta;
                k22 += delta;
                det = k11 * k22 - k12 * k12;
            }
            float inv = 1f / det;
            M11 = k22 * inv;
            M12 = -k12 * inv;
            M22 = k11 * inv;
        }

        /// <summary>Applies the angular impulses along <paramref name="u1"/>, <paramref name="u2"/>.</summary>
        public static void Apply(ref SolverBody a, ref SolverBody b, Vector3 u1, Vector3 u2, float l1, float l2)
        {
            RotationLockPart.Apply(ref a, ref b, l1 * u1 + l2 * u2);
        }

        /// <summary>Applies the accumulated impulses (warm start).</summary>
        public readonly void WarmStart(ref SolverBody a, ref SolverBody b, Vector3 u1, Vector3 u2) => Apply(ref a, ref b, u1, u2, Impulse1, Impulse2);

        /// <summary>One update of both rows; <paramref name="c1"/>, <paramref name="c2"/> are the errors a1.b2 and a1.c2.</summary>
        public void Solve(ref SolverBody a, ref SolverBody b, Vector3 u1, Vector3 u2, float c1, float c2, in Softness soft, bool useBias)
        {
            Vector3 w = b.AngularVelocity - a.AngularVelocity;
            float v1 = Vector3.Dot(u1, w), v2 = Vector3.Dot(u2, w);
            float ms = 1, isc = 0;
            if (useBias)
            {
                // The two errors' bias as one vector, so its cap keeps its direction.
                float b1 = soft.BiasRate * c1, b2 = soft.BiasRate * c2;
                soft.Capped(MathF.Sqrt(b1 * b1 + b2 * b2), out float k, out ms, out isc);
                v1 += k * b1;
                v2 += k * b2;
            }
            float d1 = -ms * (M11 * v1 + M12 * v2) - isc * Impulse1;
            float d2 = -ms * (M12 * v1 + M22 * v2) - isc * Impulse2;
            Impulse1 += d1;
            Impulse2 += d2;
            Apply(ref a, ref b, u1, u2, d1, d2);
        }

        /// <summary>Non-linear Gauss-Seidel on the two errors, their length capped at <paramref name="maxC"/> rad.</summary>
        public readonly void SolvePosition(ref SolverBody a, ref SolverBody b, Vector3 u1, Vector3 u2, float c1, float c2, float beta, float maxC)
        {
            float length = MathF.Sqrt(c1 * c1 + c2 * c2);
            if (length > maxC)
            {
                c1 *= maxC / length;
                c2 *= maxC / length;
            }
            float l1 = -beta * (M11 * c1 + M12 * c2);
            float l2 = -beta * (M12 * c1 + M22 * c2);
            Vector3 l = l1 * u1 + l2 * u2;
            a.Rotate(-(a.InverseInertia * l));
            b.Rotate(b.InverseInertia * l);
        }
    }
}
