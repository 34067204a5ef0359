using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace Fulcrum.Dynamics
{
    /// <summary>A cone-twist joint's parts: point, the swing-cone row, two twist limit rows, friction.</summary>
    internal struct ConeTwistJointParts
    {
        public PointConstraintPart Point;
        public AxisConstraintPart Cone, LowerLimit, UpperLimit;
        /// <summary>Joint friction's accumulated angular impulse on B (world, N m s per (sub)step).</summary>
        public Vector3 FrictionImpulse;

        /// <summary>Scales the accumulated impulses (a new (sub)step length, warm-start factor).</summary>
        public void Scale(float s)
        {
            Point.Impulse *= s;
            LowerLimit.Impulse *= s;
            UpperLimit.Impulse *= s;
            Cone.Impulse *= s;
            FrictionImpulse *= s;
        }
    }

    /// <summary>
    /// "coneTwist": a ball joint whose swing (the angle between the frames' x axes) stays in a
    /// cone and whose twist about the mean axis stays within limits; joint friction (ragdolls).
    /// </summary>
    internal struct ConeTwistJointSolver : IJointKind
    {
        Vector3 _swingAxis, _t;
        float _swing, _twist;
        bool _cone, _limits;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Setup(ref JointData j, in SolverBody a, in SolverBody b, in JointGeometry g, bool mass)
        {
            ref ConeTwistJointParts k = ref j.Parts.ConeTwist;
            Quaternion fA = g.FrameA, fB = g.FrameB;
            Vector3 ta = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 tb = Vector3.Transform(Vector3.UnitX, fB);
            // Swing: the angle between the twist axes grows at s.(wB - wA), s = unit(ta x tb).
            Vector3 s = Vector3.Cross(ta, tb);
            float sinSwing = s.Length();
            _swing = MathF.Atan2(sinSwing, Vector3.Dot(ta, tb));
            _swingAxis = sinSwing > 1e-6f ? s / sinSwing : Vector3.Transform(Vector3.UnitY, fA);
            _cone = j.ConeAngle < MathF.PI;
            // Twist about the mean twist axis.
            Vector3 t = ta + tb;
            float tl = t.Length();
            _t = tl > 1e-6f ? t / tl : ta;
            _twist = JointSolver.TwistAngle(fA, fB);
            _limits = j.TwistAngle < MathF.PI;
            k.Cone.SetAngular(-_swingAxis);
            JointLimits.SetAngular(ref k.LowerLimit, ref k.UpperLimit, _t);
            if (!mass) return;
            k.Point.ComputeMass(a, b, g.ArmA, g.ArmB);
            k.Cone.ComputeMass(a, b);
            k.LowerLimit.ComputeMass(a, b);
            k.UpperLimit.EffectiveMass = k.LowerLimit.EffectiveMass;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void WarmStart(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g)
        {
            ref ConeTwistJointParts k = ref j.Parts.ConeTwist;
            JointSolver.WarmStartFriction(j.FrictionTorque, k.FrictionImpulse, ref a, ref b);
            if (_cone) k.Cone.WarmStart(ref a, ref b);
            JointLimits.WarmStart(k.LowerLimit, k.UpperLimit, _limits, _limits, ref a, ref b);
            k.Point.WarmStart(ref a, ref b, g.ArmA, g.ArmB);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Solve(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, in JointSolver.StepParameters p, bool useBias)
        {
            ref ConeTwistJointParts k = ref j.Parts.ConeTwist;
            JointSolver.SolveFriction(j.FrictionTorque, ref k.FrictionImpulse, ref a, ref b, Vector3.Zero, p.H);
            // The limits the joint tree's block holds this step are its, and a limit still ahead is
            // left to the block where the block takes the joint's limits (JointTreeSolver.RestingCone;
            // bits of DirectLimit: 1 the cone, 2 the lower twist limit, 4 the upper, 8 the block takes
            // them), as a tree hinge leaves its stop: solved here, between the warm start and the
            // block, a limit met a light arm's transient velocities under a 1e5 kg load and the arm tore loose.
            bool tree = (j.DirectLimit & 8) != 0;
            if (_cone && (j.DirectLimit & 1) == 0 && !(tree && _swing < j.ConeAngle)) k.Cone.SolveLimit(ref a, ref b, j.ConeAngle - _swing, p.Joint, p.InvH, useBias);
            if (_limits)
            {
                if ((j.DirectLimit & 2) == 0 && !(tree && _twist > -j.TwistAngle)) k.LowerLimit.SolveLimit(ref a, ref b, _twist + j.TwistAngle, p.Joint, p.InvH, useBias);
                if ((j.DirectLimit & 4) == 0 && !(tree && _twist < j.TwistAngle)) k.UpperLimit.SolveLimit(ref a, ref b, j.TwistAngle - _twist, p.Joint, p.InvH, useBias);
            }
            if (!j.DirectPoint) k.Point.Solve(ref a, ref b, g.ArmA, g.ArmB, g.Gap, p.Joint, useBias);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SolvePosition(ref JointData j, ref SolverBody a, ref SolverBody b, in JointGeometry g, float beta, float maxC)
        {
            ref ConeTwistJointParts k = ref j.Parts.ConeTwist;
            if (_cone) k.Cone.SolvePosition(ref a, ref b, MathF.Min(j.ConeAngle - _swing, 0), beta, maxC);
            JointLimits.SolvePosition(k.LowerLimit, k.UpperLimit, _limits, _limits, ref a, ref b, _twist + j.TwistAngle, j.TwistAngle - _twist, beta, maxC);
            k.Point.SolvePosition(ref a, ref b, g.ArmA, g.ArmB, g.Gap, beta, maxC);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Report(ref JointData j, in JointGeometry g, in JointSolver.StepParameters p)
        {
            ref ConeTwistJointParts k = ref j.Parts.ConeTwist;
            Vector3 torque = -k.Cone.Impulse * _swingAxis + (k.LowerLimit.Impulse - k.UpperLimit.Impulse) * _t + k.FrictionImpulse;
            JointSolver.Report(ref j, p, k.Point.Impulse, torque, g.Gap.Length());
        }
    }
}
