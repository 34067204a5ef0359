using System.Numerics;
using System.Runtime.CompilerServices;

namespace Fulcrum.Dynamics
{
    /// <summary>A ball joint's parts: the anchors coincide; joint friction resists rotation.</summary>
    internal struct BallJointParts
    {
        public PointConstraintPart Point;
        /// <summary>Joint friction's accumulated angular impulse on B (world, N m s per (sub)step).</summary>
        public Vector3 FrictionImpulse;

        /// <summary>Scales the accumulated impulses (a new (sub)step length, warm-start factor).</summary>
        public void Scale(float s)
        {
            Point.Impulse *= s;
            FrictionImpulse *= s;
        }
    }

    /// <summary>"ball": <see cref="PointConstraintPart"/> and joint friction; free rotation otherwise.</summary>
    internal struct BallJointSolver : IJointKind
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Setup(ref JointData j, in SolverBody a, in SolverBody b, in JointGeometry g, bool mass)
        {
            if (mass) j.Parts.Ball.Point.ComputeMass(a, b, g.ArmA, g.ArmB);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void WarmStart(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g)
        {
            ref BallJointParts k = ref j.Parts.Ball;
            JointSolver.WarmStartFriction(j.FrictionTorque, k.FrictionImpulse, ref a, ref b);
            k.Point.WarmStart(ref a, ref b, g.ArmA, g.ArmB);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Solve(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, in JointSolver.StepParameters p, bool useBias)
        {
            ref BallJointParts k = ref j.Parts.Ball;
            JointSolver.SolveFriction(j.FrictionTorque, ref k.FrictionImpulse, ref a, ref b, Vector3.Zero, p.H);
            if (!j.DirectPoint) k.Point.Solve(ref a, ref b, g.ArmA, g.ArmB, g.Gap, p.Joint, useBias);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SolvePosition(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, float beta, float maxC) =>
            j.Parts.Ball.Point.SolvePosition(ref a, ref b, g.ArmA, g.ArmB, g.Gap, beta, maxC);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Report(ref JointData j, in JointGeometry g, in JointSolver.StepParameters p) =>
            JointSolver.Report(ref j, p, j.Parts.Ball.Point.Impulse, j.Parts.Ball.FrictionImpulse, g.Gap.Length());
    }
}
