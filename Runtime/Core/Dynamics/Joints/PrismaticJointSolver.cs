using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace Fulcrum.Dynamics
{
    /// <summary>A prismatic joint's parts: two rows across the slide axis, the rotation lock, slide limits and motor.</summary>
    internal struct PrismaticJointParts
    {
        /// <summary>The rows across the slide axis.</summary>
        public AxisConstraintPart Perp1, Perp2;
        public RotationLockPart Lock;
        public AxisConstraintPart LowerLimit, UpperLimit, Motor;

        /// <summary>Scales the accumulated impulses (a new (sub)step length, warm-start factor).</summary>
        public void Scale(float s)
        {
            Lock.Impulse *= s;
            Perp1.Impulse *= s;
            Perp2.Impulse *= s;
            LowerLimit.Impulse *= s;
            UpperLimit.Impulse *= s;
            Motor.Impulse *= s;
        }
    }

    /// <summary>"prismatic": the bodies slide along A's x axis without turning, with optional limits and motor.</summary>
    internal struct PrismaticJointSolver : IJointKind
    {
        Vector3 _axis, _p1, _p2, _angle;
        float _c1, _c2, _x;
        bool _lower, _upper, _motor;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Setup(ref JointData j, in SolverBody a, in SolverBody b, in JointGeometry g, bool mass)
        {
            ref PrismaticJointParts k = ref j.Parts.Prismatic;
            Quaternion fA = g.FrameA;
            Vector3 d = g.Gap, rB = g.ArmB;
            Vector3 axis = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 p1 = Vector3.Transform(Vector3.UnitY, fA);
            Vector3 p2 = Vector3.Transform(Vector3.UnitZ, fA);
            // The slide axis turns with A, so A's arm for these rows reaches to B's anchor: rA + d.
            Vector3 armA = g.ArmA + d;
            _axis = axis;
            _p1 = p1;
            _p2 = p2;
            _c1 = Vector3.Dot(p1, d);
            _c2 = Vector3.Dot(p2, d);
            _x = Vector3.Dot(axis, d);
            _angle = RotationLockPart.Error(fA, g.FrameB);
            _lower = j.HasLowerLimit;
            _upper = j.HasUpperLimit;
            _motor = j.MaxMotorForce > 0;
            k.Perp1.SetLinear(armA, rB, p1);
            k.Perp2.SetLinear(armA, rB, p2);
            JointLimits.SetLinear(ref k.LowerLimit, ref k.UpperLimit, armA, rB, axis);
            k.Motor.SetLinear(armA, rB, axis);
            if (!mass) return;
            k.Perp1.ComputeMass(a, b);
            k.Perp2.ComputeMass(a, b);
            k.Motor.ComputeMass(a, b);
            k.LowerLimit.EffectiveMass = k.UpperLimit.EffectiveMass = k.Motor.EffectiveMass;
            k.Lock.ComputeMass(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void WarmStart(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g)
        {
            ref PrismaticJointParts k = ref j.Parts.Prismatic;
            if (_motor) k.Motor.WarmStart(ref a, ref b);
            JointLimits.WarmStart(k.LowerLimit, k.UpperLimit, _lower, _upper, ref a, ref b);
            k.Lock.WarmStart(ref a, ref b);
            k.Perp1.WarmStart(ref a, ref b);
            k.Perp2.WarmStart(ref a, ref b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Solve(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, in JointSolver.StepParameters p, bool useBias)
        {
            ref PrismaticJointParts k = ref j.Parts.Prismatic;
            if (_motor) JointSolver.SolveMotor(ref k.Motor, ref a, ref b, j.MotorSpeed, j.MaxMotorForce * p.H);
            // A slider in a joint tree leaves a limit it rests on, and one still ahead, to the tree
            // (JointTreeSolver.RestingSlide), as a tree hinge does its stop.
            bool tree = j.DirectPoint;
            if (_lower && j.DirectLimit <= 0 && !(tree && _x > j.Lower)) k.LowerLimit.SolveLimit(ref a, ref b, _x - j.Lower, p.Joint, p.InvH, useBias);
            if (_upper && j.DirectLimit >= 0 && !(tree && _x < j.Upper)) k.UpperLimit.SolveLimit(ref a, ref b, j.Upper - _x, p.Joint, p.InvH, useBias);
            if (tree) return; // the lock and the rows across the axis are in the joint trees' block
            k.Lock.Solve(ref a, ref b, _angle, p.Joint, useBias);
            k.Perp1.SolveEquality(ref a, ref b, _c1, p.Joint, useBias);
            k.Perp2.SolveEquality(ref a, ref b, _c2, p.Joint, useBias);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SolvePosition(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, float beta, float maxC)
        {
            ref PrismaticJointParts k = ref j.Parts.Prismatic;
            JointLimits.SolvePosition(k.LowerLimit, k.UpperLimit, _lower, _upper, ref a, ref b, _x - j.Lower, j.Upper - _x, beta, maxC);
            k.Lock.SolvePosition(ref a, ref b, _angle, beta, maxC);
            k.Perp1.SolvePosition(ref a, ref b, _c1, beta, maxC);
            k.Perp2.SolvePosition(ref a, ref b, _c2, beta, maxC);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Report(ref JointData j, in JointGeometry g, in JointSolver.StepParameters p)
        {
            ref PrismaticJointParts k = ref j.Parts.Prismatic;
            Vector3 force = k.Perp1.Impulse * _p1 + k.Perp2.Impulse * _p2
                + (k.Motor.Impulse + k.LowerLimit.Impulse - k.UpperLimit.Impulse) * _axis;
            float slide = MathF.Max(0, MathF.Max(_lower ? j.Lower - _x : 0, _upper ? _x - j.Upper : 0));
            JointSolver.Report(ref j, p, force, k.Lock.Impulse, MathF.Sqrt(_c1 * _c1 + _c2 * _c2) + slide);
        }
    }
}
