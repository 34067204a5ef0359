using System;
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Solves joints by kind, each assembled from constraint parts:
    /// <list type="table">
    /// <item><term>ball</term><description><see cref="PointConstraintPart"/></description></item>
    /// <item><term>hinge</term><description>point, <see cref="HingeRotationPart"/>, angle limits, motor, spring (angular <see cref="AxisConstraintPart"/>s about the axis)</description></item>
    /// <item><term>distance</term><description>a rigid length row, or min/max limit rows, and a spring row along the anchors' line</description></item>
    /// <item><term>fixed</term><description>point, <see cref="RotationLockPart"/></description></item>
    /// <item><term>prismatic</term><description>two rows across the slide axis, rotation lock, slide limits and motor</description></item>
    /// <item><term>coneTwist</term><description>point, a swing-cone row and two twist limit rows</description></item>
    /// </list>
    /// Every pass (prepare, warm start, solve, position correction, report) first rebuilds the
    /// joint's current geometry from the bodies' motion within the step: arms rA = dqA rA0,
    /// the anchor gap d = (cB + rB) - (cA + rA), joint frames dqA fA0 and dqB fB0. Limits are
    /// one-sided rows that act speculatively (they let a gap C close in one step); motors are
    /// rows driving J v to the motor speed with a bounded impulse; springs are soft rows with
    /// the joint's own frequency and damping, active in every pass.
    /// </summary>
    internal static class JointSolver
    {
        /// <summary>What a call to <see cref="Run"/> does.</summary>
        public enum Pass : byte { Prepare, WarmStart, Solve, Relax, Position, Report }

        /// <summary>Per-(sub)step constants shared by all joints.</summary>
        public struct StepParameters
        {
            /// <summary>Softness of the joints' own rows (point, rotation, limits) when biased.</summary>
            public Softness Joint;
            /// <summary>The (sub)step, s, and its inverse.</summary>
            public float H, InvH;
            /// <summary>Baumgarte factor of the position passes.</summary>
            public float Beta;
        }

        /// <summary>
        /// Fills the step geometry of a joint (arms, frames, centre offset) from the bodies'
        /// poses at the start of the step and scales its impulses by <paramref name="warmScale"/>.
        /// </summary>
        public static void Begin(ref JointData j, BodyStorage bodies, float h, float warmScale)
        {
            Pose(bodies, j.BodyA, out Vector3 originA, out Quaternion qA, out Vector3 cA);
            Pose(bodies, j.BodyB, out Vector3 originB, out Quaternion qB, out Vector3 cB);
            j.ArmA = originA + Vector3.Transform(j.LocalAnchorA, qA) - cA;
            j.ArmB = originB + Vector3.Transform(j.LocalAnchorB, qB) - cB;
            j.DeltaCenter = cB - cA;
            j.FrameA = qA * j.LocalFrameA;
            j.FrameB = qB * j.LocalFrameB;
            // The parts hold impulses per (sub)step: rescale when the (sub)step changed.
            float scale = warmScale * (j.StepDt > 0 ? h / j.StepDt : 1f);
            ScaleImpulses(ref j, scale);
            j.StepDt = h;
            j.SpringSoftness = Softness.Make(j.SpringHertz, j.SpringDamping, h);
        }

        static void Pose(BodyStorage b, int slot, out Vector3 origin, out Quaternion q, out Vector3 center)
        {
            if (slot < 0)
            {
                origin = Vector3.Zero;
                q = Quaternion.Identity;
                center = Vector3.Zero;
                return;
            }
            origin = b.Position[slot];
            q = b.Rotation[slot];
            center = b.Center[slot];
        }

        static void ScaleImpulses(ref JointData j, float s)
        {
            j.Point.Impulse *= s;
            j.Lock.Impulse *= s;
            j.HingeRotation.Impulse1 *= s;
            j.HingeRotation.Impulse2 *= s;
            j.Perp1.Impulse *= s;
            j.Perp2.Impulse *= s;
            j.Length.Impulse *= s;
            j.LowerLimit.Impulse *= s;
            j.UpperLimit.Impulse *= s;
            j.Cone.Impulse *= s;
            j.Motor.Impulse *= s;
            j.Spring.Impulse *= s;
            j.FrictionImpulse *= s;
        }

        /// <summary>Runs one pass of joint <paramref name="j"/> on copies of its bodies (written back by the caller).</summary>
        public static void Run(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p)
        {
            Vector3 rA = a.RotateByDelta(j.ArmA);
            Vector3 rB = b.RotateByDelta(j.ArmB);
            Vector3 d = (b.DeltaPosition - a.DeltaPosition) + j.DeltaCenter + rB - rA;
            Quaternion fA = a.DeltaRotation * j.FrameA;
            Quaternion fB = b.DeltaRotation * j.FrameB;
            switch (j.Kind)
            {
                case JointKind.Ball: Ball(ref j, ref a, ref b, pass, p, rA, rB, d); break;
                case JointKind.Hinge: Hinge(ref j, ref a, ref b, pass, p, rA, rB, d, fA, fB); break;
                case JointKind.Distance: Distance(ref j, ref a, ref b, pass, p, rA, rB, d); break;
                case JointKind.Fixed: Fixed(ref j, ref a, ref b, pass, p, rA, rB, d, fA, fB); break;
                case JointKind.Prismatic: Prismatic(ref j, ref a, ref b, pass, p, rA, rB, d, fA, fB); break;
                default: ConeTwist(ref j, ref a, ref b, pass, p, rA, rB, d, fA, fB); break;
            }
        }

        // ---- kinds ------------------------------------------------------------------------

        static void Ball(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p, Vector3 rA, Vector3 rB, Vector3 d)
        {
            if (NeedsMass(pass))
            {
                j.Point.ComputeMass(a, b, rA, rB);
            }
            switch (pass)
            {
                case Pass.Prepare: break;
                case Pass.WarmStart:
                    WarmStartFriction(j, ref a, ref b);
                    j.Point.WarmStart(ref a, ref b, rA, rB);
                    break;
                case Pass.Solve:
                case Pass.Relax:
                    SolveFriction(ref j, ref a, ref b, Vector3.Zero, p.H);
                    j.Point.Solve(ref a, ref b, rA, rB, d, p.Joint, pass == Pass.Solve);
                    break;
                case Pass.Position: j.Point.SolvePosition(ref a, ref b, rA, rB, d, p.Beta); break;
                default: Report(ref j, p, j.Point.Impulse, j.FrictionImpulse, d.Length()); break;
            }
        }

        static void Fixed(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p,
            Vector3 rA, Vector3 rB, Vector3 d, Quaternion fA, Quaternion fB)
        {
            Vector3 angle = RotationLockPart.Error(fA, fB);
            if (NeedsMass(pass))
            {
                j.Point.ComputeMass(a, b, rA, rB);
                j.Lock.ComputeMass(a, b);
            }
            switch (pass)
            {
                case Pass.Prepare: break;
                case Pass.WarmStart:
                    j.Lock.WarmStart(ref a, ref b);
                    j.Point.WarmStart(ref a, ref b, rA, rB);
                    break;
                case Pass.Solve:
                case Pass.Relax:
                    j.Lock.Solve(ref a, ref b, angle, p.Joint, pass == Pass.Solve);
                    j.Point.Solve(ref a, ref b, rA, rB, d, p.Joint, pass == Pass.Solve);
                    break;
                case Pass.Position:
                    j.Lock.SolvePosition(ref a, ref b, angle, p.Beta);
                    j.Point.SolvePosition(ref a, ref b, rA, rB, d, p.Beta);
                    break;
                default: Report(ref j, p, j.Point.Impulse, j.Lock.Impulse, d.Length()); break;
            }
        }

        /// <summary>cos 30 degrees: past this misalignment a hinge realigns its axes with one swing row.</summary>
        const float SwingCosine = 0.8660254f;

        static void Hinge(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p,
            Vector3 rA, Vector3 rB, Vector3 d, Quaternion fA, Quaternion fB)
        {
            Vector3 axis = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 b2 = Vector3.Transform(Vector3.UnitY, fB);
            Vector3 c2 = Vector3.Transform(Vector3.UnitZ, fB);
            Vector3 u1 = Vector3.Cross(b2, axis), u2 = Vector3.Cross(c2, axis);
            float e1 = Vector3.Dot(axis, b2), e2 = Vector3.Dot(axis, c2);
            float angle = TwistAngle(fA, fB);
            bool lower = j.HasLowerLimit, upper = j.HasUpperLimit, motor = j.MaxMotorForce > 0, spring = j.SpringHertz > 0;
            // The two rotation rows are a small-angle form: their directions b2 x a1, c2 x a1 lose
            // the swing that realigns the axes as the misalignment grows, and at 90 degrees it is
            // gone (the hinge stayed misaligned). Past SwingAngle the axes are realigned instead
            // by one row about n = a1 x a2 whose error is the angle between them (the cone part,
            // which a hinge does not otherwise use), and the small-angle rows rest.
            Vector3 a2 = Vector3.Transform(Vector3.UnitX, fB);
            float cosine = Vector3.Dot(axis, a2);
            bool swing = cosine < SwingCosine;
            float swingAngle = 0;
            if (swing)
            {
                Vector3 n = Vector3.Cross(axis, a2);
                float sine = n.Length();
                n = sine > 1e-6f ? n / sine : b2; // antiparallel: any direction across the axis
                swingAngle = MathF.Atan2(sine, cosine);
                j.Cone.SetAngular(n);
                j.HingeRotation.Impulse1 = j.HingeRotation.Impulse2 = 0;
            }
            else j.Cone.Impulse = 0;
            j.LowerLimit.SetAngular(axis);
            j.UpperLimit.SetAngular(-axis);
            j.Motor.SetAngular(axis);
            j.Spring.SetAngular(axis);
            if (NeedsMass(pass))
            {
                j.Point.ComputeMass(a, b, rA, rB);
                j.HingeRotation.ComputeMass(a, b, u1, u2);
                if (swing) j.Cone.ComputeMass(a, b);
                j.Motor.ComputeMass(a, b);
                j.LowerLimit.EffectiveMass = j.UpperLimit.EffectiveMass = j.Spring.EffectiveMass = j.Motor.EffectiveMass;
            }
            switch (pass)
            {
                case Pass.Prepare: break;
                case Pass.WarmStart:
                    if (spring) j.Spring.WarmStart(ref a, ref b);
                    WarmStartFriction(j, ref a, ref b);
                    if (motor) j.Motor.WarmStart(ref a, ref b);
                    if (lower) j.LowerLimit.WarmStart(ref a, ref b);
                    if (upper) j.UpperLimit.WarmStart(ref a, ref b);
                    if (swing) j.Cone.WarmStart(ref a, ref b);
                    else j.HingeRotation.WarmStart(ref a, ref b, u1, u2);
                    j.Point.WarmStart(ref a, ref b, rA, rB);
                    break;
                case Pass.Solve:
                case Pass.Relax:
                {
                    bool useBias = pass == Pass.Solve;
                    if (spring) SolveSpring(ref j.Spring, ref a, ref b, angle, j.SpringSoftness);
                    SolveFriction(ref j, ref a, ref b, axis, p.H);
                    if (motor) SolveMotor(ref j.Motor, ref a, ref b, j.MotorSpeed, j.MaxMotorForce * p.H);
                    if (lower) j.LowerLimit.SolveLimit(ref a, ref b, angle - j.Lower, p.Joint, p.InvH, useBias);
                    if (upper) j.UpperLimit.SolveLimit(ref a, ref b, j.Upper - angle, p.Joint, p.InvH, useBias);
                    if (swing) j.Cone.SolveEquality(ref a, ref b, swingAngle, p.Joint, useBias);
                    else j.HingeRotation.Solve(ref a, ref b, u1, u2, e1, e2, p.Joint, useBias);
                    j.Point.Solve(ref a, ref b, rA, rB, d, p.Joint, useBias);
                    break;
                }
                case Pass.Position:
                    if (lower) j.LowerLimit.SolvePosition(ref a, ref b, MathF.Min(angle - j.Lower, 0), p.Beta);
                    if (upper) j.UpperLimit.SolvePosition(ref a, ref b, MathF.Min(j.Upper - angle, 0), p.Beta);
                    if (swing) j.Cone.SolvePosition(ref a, ref b, swingAngle, p.Beta);
                    else j.HingeRotation.SolvePosition(ref a, ref b, u1, u2, e1, e2, p.Beta);
                    j.Point.SolvePosition(ref a, ref b, rA, rB, d, p.Beta);
                    break;
                default:
                {
                    Vector3 torque = j.HingeRotation.Impulse1 * u1 + j.HingeRotation.Impulse2 * u2 + j.Cone.Impulse * j.Cone.AngularB
                        + (j.Motor.Impulse + j.Spring.Impulse + j.LowerLimit.Impulse - j.UpperLimit.Impulse) * axis + j.FrictionImpulse;
                    Report(ref j, p, j.Point.Impulse, torque, d.Length());
                    break;
                }
            }
        }

        static void Distance(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p, Vector3 rA, Vector3 rB, Vector3 d)
        {
            float length = d.Length();
            Vector3 n = length > 1e-6f ? d / length : Vector3.UnitY;
            bool rigid = j.MinLength == j.MaxLength;
            bool lower = !rigid && j.HasLowerLimit, upper = !rigid && j.HasUpperLimit, spring = !rigid && j.SpringHertz > 0;
            j.Length.SetLinear(rA, rB, n);
            j.LowerLimit.SetLinear(rA, rB, n);
            j.UpperLimit.SetLinear(rA, rB, -n);
            j.Spring.SetLinear(rA, rB, n);
            if (NeedsMass(pass))
            {
                j.Length.ComputeMass(a, b);
                j.LowerLimit.EffectiveMass = j.UpperLimit.EffectiveMass = j.Spring.EffectiveMass = j.Length.EffectiveMass;
            }
            switch (pass)
            {
                case Pass.Prepare: break;
                case Pass.WarmStart:
                    if (rigid) j.Length.WarmStart(ref a, ref b);
                    if (spring) j.Spring.WarmStart(ref a, ref b);
                    if (lower) j.LowerLimit.WarmStart(ref a, ref b);
                    if (upper) j.UpperLimit.WarmStart(ref a, ref b);
                    break;
                case Pass.Solve:
                case Pass.Relax:
                {
                    bool useBias = pass == Pass.Solve;
                    if (rigid) j.Length.SolveEquality(ref a, ref b, length - j.MinLength, p.Joint, useBias);
                    if (spring) SolveSpring(ref j.Spring, ref a, ref b, length - j.RestLength, j.SpringSoftness);
                    if (lower) j.LowerLimit.SolveLimit(ref a, ref b, length - j.MinLength, p.Joint, p.InvH, useBias);
                    if (upper) j.UpperLimit.SolveLimit(ref a, ref b, j.MaxLength - length, p.Joint, p.InvH, useBias);
                    break;
                }
                case Pass.Position:
                    if (rigid) j.Length.SolvePosition(ref a, ref b, length - j.MinLength, p.Beta);
                    if (lower) j.LowerLimit.SolvePosition(ref a, ref b, MathF.Min(length - j.MinLength, 0), p.Beta);
                    if (upper) j.UpperLimit.SolvePosition(ref a, ref b, MathF.Min(j.MaxLength - length, 0), p.Beta);
                    break;
                default:
                {
                    float error = rigid ? MathF.Abs(length - j.MinLength)
                        : MathF.Max(0, MathF.Max(lower ? j.MinLength - length : 0, upper ? length - j.MaxLength : 0));
                    float impulse = j.Length.Impulse + j.Spring.Impulse + j.LowerLimit.Impulse - j.UpperLimit.Impulse;
                    Report(ref j, p, impulse * n, Vector3.Zero, error);
                    break;
                }
            }
        }

        static void Prismatic(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p,
            Vector3 rA, Vector3 rB, Vector3 d, Quaternion fA, Quaternion fB)
        {
            Vector3 axis = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 p1 = Vector3.Transform(Vector3.UnitY, fA);
            Vector3 p2 = Vector3.Transform(Vector3.UnitZ, fA);
            // The slide axis turns with A, so A's arm for these rows reaches to B's anchor: rA + d.
            Vector3 armA = rA + d;
            float c1 = Vector3.Dot(p1, d), c2 = Vector3.Dot(p2, d), x = Vector3.Dot(axis, d);
            Vector3 angle = RotationLockPart.Error(fA, fB);
            bool lower = j.HasLowerLimit, upper = j.HasUpperLimit, motor = j.MaxMotorForce > 0;
            j.Perp1.SetLinear(armA, rB, p1);
            j.Perp2.SetLinear(armA, rB, p2);
            j.LowerLimit.SetLinear(armA, rB, axis);
            j.UpperLimit.SetLinear(armA, rB, -axis);
            j.Motor.SetLinear(armA, rB, axis);
            if (NeedsMass(pass))
            {
                j.Perp1.ComputeMass(a, b);
                j.Perp2.ComputeMass(a, b);
                j.Motor.ComputeMass(a, b);
                j.LowerLimit.EffectiveMass = j.UpperLimit.EffectiveMass = j.Motor.EffectiveMass;
                j.Lock.ComputeMass(a, b);
            }
            switch (pass)
            {
                case Pass.Prepare: break;
                case Pass.WarmStart:
                    if (motor) j.Motor.WarmStart(ref a, ref b);
                    if (lower) j.LowerLimit.WarmStart(ref a, ref b);
                    if (upper) j.UpperLimit.WarmStart(ref a, ref b);
                    j.Lock.WarmStart(ref a, ref b);
                    j.Perp1.WarmStart(ref a, ref b);
                    j.Perp2.WarmStart(ref a, ref b);
                    break;
                case Pass.Solve:
                case Pass.Relax:
                {
                    bool useBias = pass == Pass.Solve;
                    if (motor) SolveMotor(ref j.Motor, ref a, ref b, j.MotorSpeed, j.MaxMotorForce * p.H);
                    if (lower) j.LowerLimit.SolveLimit(ref a, ref b, x - j.Lower, p.Joint, p.InvH, useBias);
                    if (upper) j.UpperLimit.SolveLimit(ref a, ref b, j.Upper - x, p.Joint, p.InvH, useBias);
                    j.Lock.Solve(ref a, ref b, angle, p.Joint, useBias);
                    j.Perp1.SolveEquality(ref a, ref b, c1, p.Joint, useBias);
                    j.Perp2.SolveEquality(ref a, ref b, c2, p.Joint, useBias);
                    break;
                }
                case Pass.Position:
                    if (lower) j.LowerLimit.SolvePosition(ref a, ref b, MathF.Min(x - j.Lower, 0), p.Beta);
                    if (upper) j.UpperLimit.SolvePosition(ref a, ref b, MathF.Min(j.Upper - x, 0), p.Beta);
                    j.Lock.SolvePosition(ref a, ref b, angle, p.Beta);
                    j.Perp1.SolvePosition(ref a, ref b, c1, p.Beta);
                    j.Perp2.SolvePosition(ref a, ref b, c2, p.Beta);
                    break;
                default:
                {
                    Vector3 force = j.Perp1.Impulse * p1 + j.Perp2.Impulse * p2
                        + (j.Motor.Impulse + j.LowerLimit.Impulse - j.UpperLimit.Impulse) * axis;
                    float slide = MathF.Max(0, MathF.Max(lower ? j.Lower - x : 0, upper ? x - j.Upper : 0));
                    Report(ref j, p, force, j.Lock.Impulse, MathF.Sqrt(c1 * c1 + c2 * c2) + slide);
                    break;
                }
            }
        }

        static void ConeTwist(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p,
            Vector3 rA, Vector3 rB, Vector3 d, Quaternion fA, Quaternion fB)
        {
            Vector3 ta = Vector3.Transform(Vector3.UnitX, fA);
            Vector3 tb = Vector3.Transform(Vector3.UnitX, fB);
            // Swing: the angle between the twist axes grows at s.(wB - wA), s = unit(ta x tb).
            Vector3 s = Vector3.Cross(ta, tb);
            float sinSwing = s.Length();
            float swing = MathF.Atan2(sinSwing, Vector3.Dot(ta, tb));
            Vector3 swingAxis = sinSwing > 1e-6f ? s / sinSwing : Vector3.Transform(Vector3.UnitY, fA);
            bool cone = j.ConeAngle < MathF.PI;
            // Twist about the mean twist axis.
            Vector3 t = ta + tb;
            float tl = t.Length();
            t = tl > 1e-6f ? t / tl : ta;
            float twist = TwistAngle(fA, fB);
            bool limits = j.TwistAngle < MathF.PI;
            j.Cone.SetAngular(-swingAxis);
            j.LowerLimit.SetAngular(t);
            j.UpperLimit.SetAngular(-t);
            if (NeedsMass(pass))
            {
                j.Point.ComputeMass(a, b, rA, rB);
                j.Cone.ComputeMass(a, b);
                j.LowerLimit.ComputeMass(a, b);
                j.UpperLimit.EffectiveMass = j.LowerLimit.EffectiveMass;
            }
            switch (pass)
            {
                case Pass.Prepare: break;
                case Pass.WarmStart:
                    WarmStartFriction(j, ref a, ref b);
                    if (cone) j.Cone.WarmStart(ref a, ref b);
                    if (limits)
                    {
                        j.LowerLimit.WarmStart(ref a, ref b);
                        j.UpperLimit.WarmStart(ref a, ref b);
                    }
                    j.Point.WarmStart(ref a, ref b, rA, rB);
                    break;
                case Pass.Solve:
                case Pass.Relax:
                {
                    bool useBias = pass == Pass.Solve;
                    SolveFriction(ref j, ref a, ref b, Vector3.Zero, p.H);
                    if (cone) j.Cone.SolveLimit(ref a, ref b, j.ConeAngle - swing, p.Joint, p.InvH, useBias);
                    if (limits)
                    {
                        j.LowerLimit.SolveLimit(ref a, ref b, twist + j.TwistAngle, p.Joint, p.InvH, useBias);
                        j.UpperLimit.SolveLimit(ref a, ref b, j.TwistAngle - twist, p.Joint, p.InvH, useBias);
                    }
                    j.Point.Solve(ref a, ref b, rA, rB, d, p.Joint, useBias);
                    break;
                }
                case Pass.Position:
                    if (cone) j.Cone.SolvePosition(ref a, ref b, MathF.Min(j.ConeAngle - swing, 0), p.Beta);
                    if (limits)
                    {
                        j.LowerLimit.SolvePosition(ref a, ref b, MathF.Min(twist + j.TwistAngle, 0), p.Beta);
                        j.UpperLimit.SolvePosition(ref a, ref b, MathF.Min(j.TwistAngle - twist, 0), p.Beta);
                    }
                    j.Point.SolvePosition(ref a, ref b, rA, rB, d, p.Beta);
                    break;
                default:
                {
                    Vector3 torque = -j.Cone.Impulse * swingAxis + (j.LowerLimit.Impulse - j.UpperLimit.Impulse) * t + j.FrictionImpulse;
                    Report(ref j, p, j.Point.Impulse, torque, d.Length());
                    break;
                }
            }
        }

        // ---- shared rows and measures -----------------------------------------------------

        // Effective masses follow the arms and axes as they turn within the step: a mass kept
        // from the start of the step is wrong in direction once an arm has turned, and where
        // K is very anisotropic (a small body far from its anchor: tangential 1/m + L^2/I
        // against radial 1/m) that error pumps energy into the joint.
        static bool NeedsMass(Pass pass) => pass == Pass.Prepare || pass == Pass.Solve || pass == Pass.Relax || pass == Pass.Position;

        /// <summary>A motor: drives J v to <paramref name="speed"/> with an impulse bounded by <paramref name="maxImpulse"/>.</summary>
        static void SolveMotor(ref AxisConstraintPart row, ref SolverBody a, ref SolverBody b, float speed, float maxImpulse) =>
            row.Solve(ref a, ref b, -speed, 1, 0, -maxImpulse, maxImpulse);

        /// <summary>Applies the joint friction's accumulated impulse (warm start).</summary>
        static void WarmStartFriction(in JointData j, ref SolverBody a, ref SolverBody b)
        {
            if (j.FrictionTorque == 0) return;
            a.AngularVelocity -= a.InverseInertia * j.FrictionImpulse;
            b.AngularVelocity += b.InverseInertia * j.FrictionImpulse;
        }

        /// <summary>
        /// Joint friction: an angular impulse that drives the relative angular velocity
        /// wB - wA to zero, its accumulated length kept within FrictionTorque h (Coulomb's law
        /// for a joint: it holds until the load exceeds the friction torque, then slips). With
        /// a nonzero <paramref name="axis"/> (a hinge) only the rotation about it is resisted.
        /// K = IA^-1 + IB^-1 in world axes; dLambda = -K^-1 (wB - wA).
        /// </summary>
        static void SolveFriction(ref JointData j, ref SolverBody a, ref SolverBody b, Vector3 axis, float h)
        {
            if (j.FrictionTorque == 0) return;
            Vector3 dw = b.AngularVelocity - a.AngularVelocity;
            Mathematics.Mat3 k = a.InverseInertia + b.InverseInertia;
            Vector3 delta;
            if (axis != Vector3.Zero)
            {
                float kAxis = Vector3.Dot(axis, k * axis);
                delta = kAxis > 1e-30f ? (-Vector3.Dot(axis, dw) / kAxis) * axis : Vector3.Zero;
            }
            else if (!k.TryInvert(out Mathematics.Mat3 mass)) return;
            else delta = -(mass * dw);
            Vector3 old = j.FrictionImpulse;
            Vector3 total = old + delta;
            float max = j.FrictionTorque * h;
            float len2 = total.LengthSquared();
            if (len2 > max * max) total *= max / MathF.Sqrt(len2);
            j.FrictionImpulse = total;
            Vector3 applied = total - old;
            a.AngularVelocity -= a.InverseInertia * applied;
            b.AngularVelocity += b.InverseInertia * applied;
        }

        /// <summary>A spring toward C = 0: a soft row with the joint's own frequency and damping.</summary>
        static void SolveSpring(ref AxisConstraintPart row, ref SolverBody a, ref SolverBody b, float C, in Softness soft) =>
            row.Solve(ref a, ref b, soft.Bias(C), soft.MassScale, soft.ImpulseScale, float.NegativeInfinity, float.PositiveInfinity);

        /// <summary>
        /// The rotation of frame B relative to frame A about A's x axis, in (-pi, pi]: the twist
        /// part of the swing-twist split of q = fA^-1 fB, 2 atan2(q.x, q.w).
        /// </summary>
        public static float TwistAngle(Quaternion fA, Quaternion fB)
        {
            Quaternion q = Quaternion.Conjugate(fA) * fB;
            float angle = 2f * MathF.Atan2(q.X, q.W);
            if (angle > MathF.PI) angle -= 2f * MathF.PI;
            else if (angle <= -MathF.PI) angle += 2f * MathF.PI;
            return angle;
        }

        static void Report(ref JointData j, in StepParameters p, Vector3 linearImpulse, Vector3 angularImpulse, float error)
        {
            j.Force = linearImpulse * p.InvH;
            j.Torque = angularImpulse * p.InvH;
            float stress = 0;
            if (j.BreakForce < float.PositiveInfinity) stress = j.Force.Length() / j.BreakForce;
            if (j.BreakTorque < float.PositiveInfinity) stress = MathF.Max(stress, j.Torque.Length() / j.BreakTorque);
            j.Stress = stress;
            j.Error = error;
        }
    }
}
