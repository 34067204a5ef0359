using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Three linear rows that make two anchor points coincide: C = (cB + rB) - (cA + rA) = 0,
    /// J v = vB + wB x rB - vA - wA x rA, solved together through the 3x3 effective mass
    /// K = (mA + mB) E - [rA] IA^-1 [rA] - [rB] IB^-1 [rB] ([r] the cross-product matrix, so
    /// that [r]^T = -[r]). The ball-and-socket part of ball, hinge, fixed and cone-twist joints.
    /// </summary>
    internal struct PointConstraintPart
    {
        /// <summary>K^-1 (zero if K is singular: two fixed bodies).</summary>
        public Mat3 EffectiveMass;
        /// <summary>Accumulated impulse on B (A gets the opposite), N s.</summary>
        public Vector3 Impulse;

        /// <summary>Builds K^-1 for the arms <paramref name="rA"/>, <paramref name="rB"/>.</summary>
        public void ComputeMass(in SolverBody a, in SolverBody b, Vector3 rA, Vector3 rB)
        {
            Mat3 sA = Mat3.Skew(rA), sB = Mat3.Skew(rB);
            Mat3 k = Mat3.Diagonal(a.LinearInverseMass + b.LinearInverseMass)
                   - sA * a.InverseInertia * sA
                   - sB * b.InverseInertia * sB;
            // Axis locks may leave directions in which the anchors cannot separate at all: solve
            // the rest (the pseudo-inverse) instead of dropping the joint with a zero inverse.
            EffectiveMass = (a.IsDynamic | b.IsDynamic) > 1 ? AxisLockMath.PseudoInverse(k) : k.Inverse();
        }

        /// <summary>Applies the impulse <paramref name="p"/> to B at rB and its opposite to A at rA.</summary>
        public static void Apply(ref SolverBody a, ref SolverBody b, Vector3 rA, Vector3 rB, Vector3 p)
        {
            a.ApplyImpulse(rA, -p);
            b.ApplyImpulse(rB, p);
        }

        /// <summary>Applies the accumulated impulse (warm start).</summary>
        public readonly void WarmStart(ref SolverBody a, ref SolverBody b, Vector3 rA, Vector3 rB) => Apply(ref a, ref b, rA, rB, Impulse);

        /// <summary>One update; with <paramref name="useBias"/> the rows are soft and pull the anchors together.</summary>
        public void Solve(ref SolverBody a, ref SolverBody b, Vector3 rA, Vector3 rB, Vector3 C, in Softness soft, bool useBias)
        {
            Vector3 jv = b.PointVelocity(rB) - a.PointVelocity(rA);
            Vector3 impulse = soft.BlockImpulse(EffectiveMass, jv, C, Impulse, useBias);
            Impulse += impulse;
            Apply(ref a, ref b, rA, rB, impulse);
        }

        /// <summary>
        /// Non-linear Gauss-Seidel: moves the bodies to remove the fraction <paramref name="beta"/>
        /// of the gap <paramref name="C"/>, its length capped at <paramref name="maxC"/>.
        /// </summary>
        public readonly void SolvePosition(ref SolverBody a, ref SolverBody b, Vector3 rA, Vector3 rB, Vector3 C, float beta, float maxC)
        {
            C = JointSolver.Cap(C, maxC);
            Vector3 p = -(EffectiveMass * (beta * C));
            a.ApplyPositionImpulse(rA, -p);
            b.ApplyPositionImpulse(rB, p);
        }
    }
}
