using System.Numerics;
using System.Runtime.CompilerServices;

namespace Fulcrum.Dynamics
{
    /// <summary>A fixed joint's parts: the anchors coincide and the frames stay aligned.</summary>
    internal struct FixedJointParts
    {
        public PointConstraintPart Point;
        public RotationLockPart Lock;

        /// <summary>Scales the accumulated impulses (a new (sub)step length, warm-start factor).</summary>
        public void Scale(float s)
        {
            Point.Impulse *= s;
            Lock.Impulse *= s;
        }
    }

    /// <summary>"fixed": <see cref="PointConstraintPart"/> and <see cref="RotationLockPart"/>, a weld.</summary>
    internal struct FixedJointSolver : IJointKind
    {
        /// <summary>The small-angle rotation error between the frames.</summary>
        Vector3 _angle;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Setup(ref JointData j, in SolverBody a, in SolverBody b, in JointGeometry g, bool mass)
        {
            _angle = RotationLockPart.Error(g.FrameA, g.FrameB);
            if (!mass) return;
            ref FixedJointParts k = ref j.Parts.Fixed;
            k.Point.ComputeMass(a, b, g.ArmA, g.ArmB);
            k.Lock.ComputeMass(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void WarmStart(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g)
        {
            ref FixedJointParts k = ref j.Parts.Fixed;
            k.Lock.WarmStart(ref a, ref b);
            k.Point.WarmStart(ref a, ref b, g.ArmA, g.ArmB);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Solve(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, in JointSolver.StepParameters p, bool useBias)
        {
            ref FixedJointParts k = ref j.Parts.Fixed;
            if (!j.DirectRotation) k.Lock.Solve(ref a, ref b, _angle, p.Joint, useBias);
            if (!j.DirectPoint) k.Point.Solve(ref a, ref b, g.ArmA, g.ArmB, g.Gap, p.Joint, useBias);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SolvePosition(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, float beta, float maxC)
        {
            ref FixedJointParts k = ref j.Parts.Fixed;
            k.Lock.SolvePosition(ref a, ref b, _angle, beta, maxC);
            k.Point.SolvePosition(ref a, ref b, g.ArmA, g.ArmB, g.Gap, beta, maxC);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Report(ref JointData j, in JointGeometry g, in JointSolver.StepParameters p) =>
            JointSolver.Report(ref j, p, j.Parts.Fixed.Point.Impulse, j.Parts.Fixed.Lock.Impulse, g.Gap.Length());
    }
}
