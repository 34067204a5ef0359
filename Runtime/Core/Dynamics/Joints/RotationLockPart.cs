using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Three angular rows that lock the relative orientation (fixed and prismatic joints):
    /// J v = wB - wA, K = IA^-1 + IB^-1. The error is the rotation vector of
    /// q_e = (qB fB)(qA fA)^-1, which is 0 when the two joint frames agree and grows at
    /// wB - wA to first order.
    /// </summary>
    internal struct RotationLockPart
    {
        /// <summary>K^-1.</summary>
        public Mat3 EffectiveMass;
        /// <summary>Accumulated angular impulse on B (A gets the opposite), N m s.</summary>
        public Vector3 Impulse;

        /// <summary>Builds K^-1.</summary>
        public void ComputeMass(in SolverBody a, in SolverBody b) =>
            // Locked rotation axes zero rows of the projected inverse inertias: invert the rest.
            EffectiveMass = (a.IsDynamic | b.IsDynamic) > 1 ? AxisLockMath.InverseOnFreeAxes(a.InverseInertia + b.InverseInertia)
                : (a.InverseInertia + b.InverseInertia).Inverse();

        /// <summary>The error vector of two world joint frames, rad.</summary>
        public static Vector3 Error(Quaternion frameA, Quaternion frameB) =>
            Rotation.ToRotationVector(frameB * Quaternion.Conjugate(frameA));

        /// <summary>Applies an angular impulse <paramref name="l"/> to B and its opposite to A.</summary>
        public static void Apply(ref SolverBody a, ref SolverBody b, Vector3 l)
        {
            a.ApplyAngularImpulse(-l);
            b.ApplyAngularImpulse(l);
        }

        /// <summary>Applies the accumulated impulse (warm start).</summary>
        public readonly void WarmStart(ref SolverBody a, ref SolverBody b) => Apply(ref a, ref b, Impulse);

        /// <summary>One update; soft and biased with <paramref name="useBias"/>.</summary>
        public void Solve(ref SolverBody a, ref SolverBody b, Vector3 C, in Softness soft, bool useBias)
        {
            Vector3 jv = b.AngularVelocity - a.AngularVelocity;
            Vector3 impulse = soft.BlockImpulse(EffectiveMass, jv, C, Impulse, useBias);
            Impulse += impulse;
            Apply(ref a, ref b, impulse);
        }

        /// <summary>Non-linear Gauss-Seidel: turns the bodies to remove the fraction <paramref name="beta"/> of the error, its angle capped at <paramref name="maxC"/> rad.</summary>
        public readonly void SolvePosition(ref SolverBody a, ref SolverBody b, Vector3 C, float beta, float maxC)
        {
            C = JointSolver.Cap(C, maxC);
            Vector3 l = -(EffectiveMass * (beta * C));
            a.Rotate(-(a.InverseInertia * l));
            b.Rotate(b.InverseInertia * l);
        }
    }
}
