using System;
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// One scalar constraint row, linear or angular: J v = n.(vB - vA) + aB.wB - aA.wA. A linear
    /// row along n with arms rA, rB has aA = rA x n, aB = rB x n; an angular row about u has
    /// n = 0 and aA = aB = u. Joints are built from these (limits, motors, springs, the
    /// perpendicular rows of a prismatic joint), as Jolt builds them from its AxisConstraintPart
    /// and AngleConstraintPart. The Jacobian and the effective mass are refreshed on every pass
    /// (arms and axes turn within the step; see JointSolver).
    /// </summary>
    internal struct AxisConstraintPart
    {
        /// <summary>Linear direction n (zero for an angular row).</summary>
        public Vector3 Linear;
        /// <summary>Angular Jacobian on A (enters with a minus sign).</summary>
        public Vector3 AngularA;
        /// <summary>Angular Jacobian on B.</summary>
        public Vector3 AngularB;
        /// <summary>1 / (J M^-1 J^T), 0 when the row cannot act.</summary>
        public float EffectiveMass;
        /// <summary>Accumulated impulse (N s, or N m s for an angular row).</summary>
        public float Impulse;

        /// <summary>A linear row along unit <paramref name="n"/> between arms <paramref name="rA"/> and <paramref name="rB"/>.</summary>
        public void SetLinear(Vector3 rA, Vector3 rB, Vector3 n)
        {
            Linear = n;
            AngularA = Vector3.Cross(rA, n);
            AngularB = Vector3.Cross(rB, n);
        }

        /// <summary>An angular row about unit <paramref name="u"/>: J v = u.(wB - wA).</summary>
        public void SetAngular(Vector3 u)
        {
            Linear = Vector3.Zero;
            AngularA = u;
            AngularB = u;
        }

        /// <summary>K = (mA + mB) n.n + aA.IA^-1 aA + aB.IB^-1 aB, inverted with a guard.</summary>
        public void ComputeMass(in SolverBody a, in SolverBody b)
        {
            float k = ((a.IsDynamic | b.IsDynamic) > 1
                      ? Vector3.Dot(a.LinearInverseMass + b.LinearInverseMass, Linear * Linear)
                      : (a.InverseMass + b.InverseMass) * Linear.LengthSquared())
                    + Vector3.Dot(AngularA, a.InverseInertia * AngularA)
                    + Vector3.Dot(AngularB, b.InverseInertia * AngularB);
            EffectiveMass = k > 1e-30f ? 1f / k : 0f;
        }

        // The linear direction as body x moves along it: without the locked translation axes.
        readonly Vector3 LinearOf(in SolverBody x) => x.IsDynamic > 1 ? AxisLockMath.MaskLinear(Linear, x.Locks) : Linear;

        /// <summary>J v.</summary>
        public readonly float Velocity(in SolverBody a, in SolverBody b) =>
            Vector3.Dot(Linear, b.LinearVelocity - a.LinearVelocity)
            + Vector3.Dot(AngularB, b.AngularVelocity) - Vector3.Dot(AngularA, a.AngularVelocity);

        /// <summary>Applies the impulse <paramref name="lambda"/> along the row to both bodies.</summary>
        public readonly void Apply(ref SolverBody a, ref SolverBody b, float lambda)
        {
            a.LinearVelocity -= (a.InverseMass * lambda) * LinearOf(a);
            a.AngularVelocity -= a.InverseInertia * (lambda * AngularA);
            b.LinearVelocity += (b.InverseMass * lambda) * LinearOf(b);
            b.AngularVelocity += b.InverseInertia * (lambda * AngularB);
        }

        /// <summary>Applies the accumulated impulse (warm start).</summary>
        public readonly void WarmStart(ref SolverBody a, ref SolverBody b) => Apply(ref a, ref b, Impulse);

        /// <summary>
        /// One Gauss-Seidel update: dLambda = -m massScale (J v + bias) - impulseScale lambda,
        /// the accumulated impulse clamped to [<paramref name="min"/>, <paramref name="max"/>].
        /// </summary>
        public void Solve(ref SolverBody a, ref SolverBody b, float bias, float massScale, float impulseScale, float min, float max)
        {
            float old = Impulse;
            float impulse = -EffectiveMass * massScale * (Velocity(a, b) + bias) - impulseScale * old;
            float total = Math.Clamp(old + impulse, min, max);
            Impulse = total;
            Apply(ref a, ref b, total - old);
        }

        /// <summary>
        /// A one-sided row keeping C &gt;= 0 (a limit): speculative while C &gt; 0 (the bodies
        /// may close the gap C in this step), soft and biased when violated and
        /// <paramref name="useBias"/>, rigid otherwise. Impulse &gt;= 0.
        /// </summary>
        public void SolveLimit(ref SolverBody a, ref SolverBody b, float C, in Softness soft, float invH, bool useBias)
        {
            if (C > 0) Solve(ref a, ref b, C * invH, 1, 0, 0, float.PositiveInfinity);
            else if (useBias)
            {
                float bias = soft.Bias(C, out float massScale, out float impulseScale);
                Solve(ref a, ref b, bias, massScale, impulseScale, 0, float.PositiveInfinity);
            }
            else Solve(ref a, ref b, 0, 1, 0, 0, float.PositiveInfinity);
        }

        /// <summary>A two-sided row keeping C = 0, soft when <paramref name="useBias"/>.</summary>
        public void SolveEquality(ref SolverBody a, ref SolverBody b, float C, in Softness soft, bool useBias)
        {
            if (useBias)
            {
                float bias = soft.Bias(C, out float massScale, out float impulseScale);
                Solve(ref a, ref b, bias, massScale, impulseScale, float.NegativeInfinity, float.PositiveInfinity);
            }
            else Solve(ref a, ref b, 0, 1, 0, float.NegativeInfinity, float.PositiveInfinity);
        }

        /// <summary>
        /// Non-linear Gauss-Seidel: moves the bodies to remove the fraction
        /// <paramref name="beta"/> of the error <paramref name="C"/> along the row, capped at
        /// <paramref name="maxC"/> (m for a linear row, rad for an angular one).
        /// </summary>
        public readonly void SolvePosition(ref SolverBody a, ref SolverBody b, float C, float beta, float maxC)
        {
            if (C == 0 || EffectiveMass == 0) return;
            C = Math.Clamp(C, -maxC, maxC);
            float lambda = -beta * C * EffectiveMass;
            a.DeltaPosition -= (a.InverseMass * lambda) * LinearOf(a);
            a.Rotate(-(a.InverseInertia * (lambda * AngularA)));
            b.DeltaPosition += (b.InverseMass * lambda) * LinearOf(b);
            b.Rotate(b.InverseInertia * (lambda * AngularB));
        }
    }
}
