using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace Fulcrum.Dynamics
{
    /// <summary>A hinge's parts: point, the two rotation rows (or the realigning swing row), limits, motor, spring, friction.</summary>
    internal struct HingeJointParts
    {
        public PointConstraintPart Point;
        public HingeRotationPart Rotation;
        /// <summary>The one row about a1 x a2 that realigns badly misaligned axes.</summary>
        public AxisConstraintPart Swing;
        public AxisConstraintPart LowerLimit, UpperLimit, Motor, Spring;
        /// <summary>Joint friction's accumulated angular impulse on B (world, N m s per (sub)step).</summary>
        public Vector3 FrictionImpulse;

        /// <summary>Scales the accumulated impulses (a new (sub)step length, warm-start factor).</summary>
        public void Scale(float s)
        {
            Point.Impulse *= s;
            Rotation.Impulse1 *= s;
            Rotation.Impulse2 *= s;
            LowerLimit.Impulse *= s;
            UpperLimit.Impulse *= s;
            Swing.Impulse *= s;
            Motor.Impulse *= s;
            Spring.Impulse *= s;
            FrictionImpulse *= s;
        }
    }

    /// <summary>
    /// "hinge": point, <see cref="HingeRotationPart"/>, angle limits, motor, spring (angular
    /// <see cref="AxisConstraintPart"/>s about the axis) and joint friction about the axis.
    /// </summary>
    internal struct HingeJointSolver : IJointKind
    {
        /// <summary>cos 30 degrees: past this misalignment a hinge realigns its axes with one swing row.</summary>
        const float SwingCosine = 0.8660254f;

        Vector3 _axis, _u1, _u2;
        float _e1, _e2, _angle, _swingAngle;
        bool _lower, _upper, _motor, _spring, _swing;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Setup(ref JointData j, in SolverBody a, in SolverBody b, in JointGeometry g, bool mass)
        {
            ref HingeJointParts k = ref j.Parts.Hinge;
            Quaternion fA = g.FrameA, fB = g.FrameB;
            Vector3 axis = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 b2 = Vector3.Transform(Vector3.UnitY, fB);
            Vector3 c2 = Vector3.Transform(Vector3.UnitZ, fB);
            _axis = axis;
            _u1 = Vector3.Cross(b2, axis);
            _u2 = Vector3.Cross(c2, axis);
            _e1 = Vector3.Dot(axis, b2);
            _e2 = Vector3.Dot(axis, c2);
            _angle = JointSolver.TwistAngle(fA, fB);
            _lower = j.HasLowerLimit;
            _upper = j.HasUpperLimit;
            _motor = j.MaxMotorForce > 0;
            _spring = j.SpringHertz > 0;
            // The two rotation rows are a small-angle form: their directions b2 x a1, c2 x a1 lose
            // the swing that realigns the axes as the misalignment grows, and at 90 degrees it is
            // gone (the hinge stayed misaligned). Past SwingCosine the axes are realigned instead
            // by one row about n = a1 x a2 whose error is the angle between them, and the
            // small-angle rows rest.
            Vector3 a2 = Vector3.Transform(Vector3.UnitX, fB);
            float cosine = Vector3.Dot(axis, a2);
            _swing = cosine < SwingCosine;
            _swingAngle = 0;
            if (_swing)
            {
                Vector3 n = Vector3.Cross(axis, a2);
                float sine = n.Length();
                n = sine > 1e-6f ? n / sine : b2; // antiparallel: any direction across the axis
                _swingAngle = MathF.Atan2(sine, cosine);
                k.Swing.SetAngular(n);
                k.Rotation.Impulse1 = k.Rotation.Impulse2 = 0;
            }
            else k.Swing.Impulse = 0;
            JointLimits.SetAngular(ref k.LowerLimit, ref k.UpperLimit, axis);
            k.Motor.SetAngular(axis);
            k.Spring.SetAngular(axis);
            if (!mass) return;
            k.Point.ComputeMass(a, b, g.ArmA, g.ArmB);
            k.Rotation.ComputeMass(a, b, _u1, _u2);
            if (_swing) k.Swing.ComputeMass(a, b);
            k.Motor.ComputeMass(a, b);
            k.LowerLimit.EffectiveMass = k.UpperLimit.EffectiveMass = k.Spring.EffectiveMass = k.Motor.EffectiveMass;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void WarmStart(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g)
        {
            ref HingeJointParts k = ref j.Parts.Hinge;
            if (_spring) k.Spring.WarmStart(ref a, ref b);
            JointSolver.WarmStartFriction(j.FrictionTorque, k.FrictionImpulse, ref a, ref b);
            if (_motor) k.Motor.WarmStart(ref a, ref b);
            JointLimits.WarmStart(k.LowerLimit, k.UpperLimit, _lower, _upper, ref a, ref b);
            if (_swing) k.Swing.WarmStart(ref a, ref b);
            else k.Rotation.WarmStart(ref a, ref b, _u1, _u2);
            k.Point.WarmStart(ref a, ref b, g.ArmA, g.ArmB);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Solve(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, in JointSolver.StepParameters p, bool useBias)
        {
            ref HingeJointParts k = ref j.Parts.Hinge;
            if (_spring) JointSolver.SolveSpring(ref k.Spring, ref a, ref b, _angle, j.SpringSoftness);
            JointSolver.SolveFriction(j.FrictionTorque, ref k.FrictionImpulse, ref a, ref b, _axis, p.H);
            if (_motor) JointSolver.SolveMotor(ref k.Motor, ref a, ref b, j.MotorSpeed, j.MaxMotorForce * p.H);
            // A hinge in a joint tree whose stop is still ahead leaves it to the tree, which takes
            // the stop in the step the hinge closes on it (JointTreeSolver.RestingLimit): solved here,
            // between the warm start and the block, it met the light arm's transient velocities
            // (a 1e5 kg load's support impulses, balanced only to the solve's precision, spun a
            // 1 kg arm at 100 rad/s for an instant) and struck 0.47 rad short of the stop.
            bool tree = j.DirectRotation;
            if (_lower && j.DirectLimit <= 0 && !(tree && _angle > j.Lower)) k.LowerLimit.SolveLimit(ref a, ref b, _angle - j.Lower, p.Joint, p.InvH, useBias);
            if (_upper && j.DirectLimit >= 0 && !(tree && _angle < j.Upper)) k.UpperLimit.SolveLimit(ref a, ref b, j.Upper - _angle, p.Joint, p.InvH, useBias);
            if (_swing) k.Swing.SolveEquality(ref a, ref b, _swingAngle, p.Joint, useBias);
            else if (!j.DirectRotation) k.Rotation.Solve(ref a, ref b, _u1, _u2, _e1, _e2, p.Joint, useBias);
            if (!j.DirectPoint) k.Point.Solve(ref a, ref b, g.ArmA, g.ArmB, g.Gap, p.Joint, useBias);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SolvePosition(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, float beta, float maxC)
        {
            ref HingeJointParts k = ref j.Parts.Hinge;
            JointLimits.SolvePosition(k.LowerLimit, k.UpperLimit, _lower, _upper, ref a, ref b, _angle - j.Lower, j.Upper - _angle, beta, maxC);
            if (_swing) k.Swing.SolvePosition(ref a, ref b, _swingAngle, beta, maxC);
            else k.Rotation.SolvePosition(ref a, ref b, _u1, _u2, _e1, _e2, beta, maxC);
            k.Point.SolvePosition(ref a, ref b, g.ArmA, g.ArmB, g.Gap, beta, maxC);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Report(ref JointData j, in JointGeometry g, in JointSolver.StepParameters p)
        {
            ref HingeJointParts k = ref j.Parts.Hinge;
            Vector3 torque = k.Rotation.Impulse1 * _u1 + k.Rotation.Impulse2 * _u2 + k.Swing.Impulse * k.Swing.AngularB
                + (k.Motor.Impulse + k.Spring.Impulse + k.LowerLimit.Impulse - k.UpperLimit.Impulse) * _axis + k.FrictionImpulse;
            JointSolver.Report(ref j, p, k.Point.Impulse, torque, g.Gap.Length());
        }
    }
}
