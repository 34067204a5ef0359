using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace Fulcrum.Dynamics
{
    /// <summary>A distance joint's parts: the rigid length row, or the min/max limit rows, and a spring row.</summary>
    internal struct DistanceJointParts
    {
        public AxisConstraintPart Length, LowerLimit, UpperLimit, Spring;

        /// <summary>Scales the accumulated impulses (a new (sub)step length, warm-start factor).</summary>
        public void Scale(float s)
        {
            Length.Impulse *= s;
            LowerLimit.Impulse *= s;
            UpperLimit.Impulse *= s;
            Spring.Impulse *= s;
        }
    }

    /// <summary>
    /// "distance": a rigid length row when min = max, else min/max limit rows and a spring row,
    /// all along the anchors' line.
    /// </summary>
    internal struct DistanceJointSolver : IJointKind
    {
        Vector3 _n;
        float _length;
        bool _rigid, _lower, _upper, _spring;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Setup(ref JointData j, in SolverBody a, in SolverBody b, in JointGeometry g, bool mass)
        {
            ref DistanceJointParts k = ref j.Parts.Distance;
            Vector3 d = g.Gap, rA = g.ArmA, rB = g.ArmB;
            float length = d.Length();
            Vector3 n = length > 1e-6f ? d / length : Vector3.UnitY;
            _length = length;
            _n = n;
            _rigid = j.MinLength == j.MaxLength;
            _lower = !_rigid && j.HasLowerLimit;
            _upper = !_rigid && j.HasUpperLimit;
            _spring = !_rigid && j.SpringHertz > 0;
            k.Length.SetLinear(rA, rB, n);
            JointLimits.SetLinear(ref k.LowerLimit, ref k.UpperLimit, rA, rB, n);
            k.Spring.SetLinear(rA, rB, n);
            if (!mass) return;
            k.Length.ComputeMass(a, b);
            k.LowerLimit.EffectiveMass = k.UpperLimit.EffectiveMass = k.Spring.EffectiveMass = k.Length.EffectiveMass;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void WarmStart(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g)
        {
            ref DistanceJointParts k = ref j.Parts.Distance;
            if (_rigid) k.Length.WarmStart(ref a, ref b);
            if (_spring) k.Spring.WarmStart(ref a, ref b);
            JointLimits.WarmStart(k.LowerLimit, k.UpperLimit, _lower, _upper, ref a, ref b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Solve(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, in JointSolver.StepParameters p, bool useBias)
        {
            ref DistanceJointParts k = ref j.Parts.Distance;
            if (_rigid && !j.DirectPoint) k.Length.SolveEquality(ref a, ref b, _length - j.MinLength, p.Joint, useBias);
            if (_spring) JointSolver.SolveSpring(ref k.Spring, ref a, ref b, _length - j.RestLength, j.SpringSoftness);
            if (_lower) k.LowerLimit.SolveLimit(ref a, ref b, _length - j.MinLength, p.Joint, p.InvH, useBias);
            if (_upper && !j.DirectPoint) k.UpperLimit.SolveLimit(ref a, ref b, j.MaxLength - _length, p.Joint, p.InvH, useBias);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SolvePosition(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, float beta, float maxC)
        {
            ref DistanceJointParts k = ref j.Parts.Distance;
            if (_rigid) k.Length.SolvePosition(ref a, ref b, _length - j.MinLength, beta, maxC);
            JointLimits.SolvePosition(k.LowerLimit, k.UpperLimit, _lower, _upper, ref a, ref b, _length - j.MinLength, j.MaxLength - _length, beta, maxC);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Report(ref JointData j, in JointGeometry g, in JointSolver.StepParameters p)
        {
            ref DistanceJointParts k = ref j.Parts.Distance;
            float error = _rigid ? MathF.Abs(_length - j.MinLength)
                : MathF.Max(0, MathF.Max(_lower ? j.MinLength - _length : 0, _upper ? _length - j.MaxLength : 0));
            float impulse = k.Length.Impulse + k.Spring.Impulse + k.LowerLimit.Impulse - k.UpperLimit.Impulse;
            JointSolver.Report(ref j, p, impulse * _n, Vector3.Zero, error);
        }
    }
}
