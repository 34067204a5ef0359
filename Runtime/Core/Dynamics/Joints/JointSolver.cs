using System;
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Solves joints: dispatches each pass to the joint's kind (one file per kind,
    /// <c>&lt;Kind&gt;JointSolver</c>, implementing <see cref="IJointKind"/>), and holds the rows
    /// the kinds share (motor, spring, friction, report). Each kind is assembled from constraint parts:
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
    /// the joint's own frequency and damping, active in every pass. A kind's parts and their
    /// accumulated impulses live in its block of <see cref="JointData.Parts"/>, overlaid on the
    /// other kinds' blocks.
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
            /// <summary>
            /// The largest error one position pass removes from one row, m or rad: the joint
            /// correction speed times the step, shared among the passes, so PGS pulls a joint
            /// created far from its target together no faster than TGS's bias does.
            /// </summary>
            public float MaxCorrection;
        }

        /// <summary>
        /// Fills the step geometry of a joint (arms, frames, centre offset) from the bodies'
        /// poses at the start of the step and scales its impulses by <paramref name="warmScale"/>
        /// (0: a cold start; the caller decides it, see <see cref="RunsAway"/>).
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
            switch (j.Kind)
            {
                case JointKind.Ball: j.Parts.Ball.Scale(scale); break;
                case JointKind.Hinge: j.Parts.Hinge.Scale(scale); break;
                case JointKind.Distance: j.Parts.Distance.Scale(scale); break;
                case JointKind.Fixed: j.Parts.Fixed.Scale(scale); break;
                case JointKind.Prismatic: j.Parts.Prismatic.Scale(scale); break;
                default: j.Parts.ConeTwist.Scale(scale); break;
            }
            j.StepDt = h;
            j.SpringSoftness = Softness.Make(j.SpringHertz, j.SpringDamping, h);
        }

        /// <summary>
        /// The sustained acceleration of a step's whole dynamic mass that bounds what a joint may
        /// carry from one (sub)step into the next, m/s^2: 1000 (about 100 g; a 5 m rope whirled
        /// at 70 m/s pulls that). A load beyond it is still solved, from a cold start. Two stiff
        /// joints that cannot both be met (a hinge and a ball joint holding one 9.9 t body to
        /// world points 2.7 m apart, WorldFuzz seed 10447) push each other with springs whose
        /// rest force is about 1e9 N; warm started up to the old bound (turning the whole mass
        /// around at the speed cap in one step, 400 times more at 60 Hz) their cancelling
        /// impulses reached 8e6 N s, lifted the body 6 m and tore it 19 m from its anchors.
        /// </summary>
        public const float MaxSustainedAcceleration = 1000f;

        /// <summary>The warm-start bound for a step moving <paramref name="mass"/> kg in (sub)steps of <paramref name="h"/> s, N s (see <see cref="RunsAway"/>).</summary>
        public static float MaxWarmImpulse(float mass, float h) => 2f * MaxSustainedAcceleration * h * mass;

        /// <summary>
        /// True when the joint's last impulse exceeds <paramref name="maxImpulse"/> (N s; per metre
        /// of arm for the angular part, the arms of the step it was solved in; <see cref="MaxWarmImpulse"/>):
        /// such a joint is not warm started. Only rows that contradict each other accumulate that
        /// much (their impulses drift along directions whose effects cancel, grow every step and
        /// overflowed to infinity in a fuzzed world).
        /// </summary>
        public static bool RunsAway(in JointData j, float maxImpulse)
        {
            float linear = j.Force.Length() * j.StepDt, angular = j.Torque.Length() * j.StepDt;
            float reach = 1f + j.ArmA.Length() + j.ArmB.Length();
            return !(linear <= maxImpulse) || !(angular <= maxImpulse * reach);
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

        /// <summary>Runs one pass of joint <paramref name="j"/> on copies of its bodies (written back by the caller).</summary>
        public static void Run(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p)
        {
            var g = new JointGeometry(j, a, b);
            switch (j.Kind)
            {
                case JointKind.Ball: Run<BallJointSolver>(ref j, ref a, ref b, pass, p, g); break;
                case JointKind.Hinge: Run<HingeJointSolver>(ref j, ref a, ref b, pass, p, g); break;
                case JointKind.Distance: Run<DistanceJointSolver>(ref j, ref a, ref b, pass, p, g); break;
                case JointKind.Fixed: Run<FixedJointSolver>(ref j, ref a, ref b, pass, p, g); break;
                case JointKind.Prismatic: Run<PrismaticJointSolver>(ref j, ref a, ref b, pass, p, g); break;
                default: Run<ConeTwistJointSolver>(ref j, ref a, ref b, pass, p, g); break;
            }
        }

        // Generic over the kind (a struct), so each kind's passes compile to direct calls, inlined
        // here (the kinds ask for it) as the one switch over kinds and passes was before.
        static void Run<T>(ref JointData j, ref SolverBody a, ref SolverBody b, Pass pass, in StepParameters p, in JointGeometry g)
            where T : struct, IJointKind
        {
            T kind = default;
            kind.Setup(ref j, a, b, g, NeedsMass(pass));
            switch (pass)
            {
                case Pass.Prepare: break;
                case Pass.WarmStart: kind.WarmStart(ref j, ref a, ref b, g); break;
                case Pass.Solve:
                case Pass.Relax: kind.Solve(ref j, ref a, ref b, g, p, pass == Pass.Solve); break;
                case Pass.Position: kind.SolvePosition(ref j, ref a, ref b, g, p.Beta, p.MaxCorrection); break;
                default: kind.Report(ref j, g, p); break;
            }
        }

        // ---- shared rows and measures -----------------------------------------------------

        /// <summary><paramref name="c"/> with its length capped at <paramref name="max"/>.</summary>
        public static Vector3 Cap(Vector3 c, float max)
        {
            float length = c.Length();
            return length > max ? c * (max / length) : c;
        }

        // Effective masses follow the arms and axes as they turn within the step: a mass kept
        // from the start of the step is wrong in direction once an arm has turned, and where
        // K is very anisotropic (a small body far from its anchor: tangential 1/m + L^2/I
        // against radial 1/m) that error pumps energy into the joint.
        static bool NeedsMass(Pass pass) => pass == Pass.Prepare || pass == Pass.Solve || pass == Pass.Relax || pass == Pass.Position;

        /// <summary>A motor: drives J v to <paramref name="speed"/> with an impulse bounded by <paramref name="maxImpulse"/>.</summary>
        public static void SolveMotor(ref AxisConstraintPart row, ref SolverBody a, ref SolverBody b, float speed, float maxImpulse) =>
            row.Solve(ref a, ref b, -speed, 1, 0, -maxImpulse, maxImpulse);

        /// <summary>Applies the joint friction's accumulated impulse <paramref name="impulse"/> (warm start).</summary>
        public static void WarmStartFriction(float frictionTorque, Vector3 impulse, ref SolverBody a, ref SolverBody b)
        {
            if (frictionTorque == 0) return;
            a.AngularVelocity -= a.InverseInertia * impulse;
            b.AngularVelocity += b.InverseInertia * impulse;
        }

        /// <summary>
        /// Joint friction: an angular impulse that drives the relative angular velocity
        /// wB - wA to zero, its accumulated length kept within FrictionTorque h (Coulomb's law
        /// for a joint: it holds until the load exceeds the friction torque, then slips). With
        /// a nonzero <paramref name="axis"/> (a hinge) only the rotation about it is resisted.
        /// K = IA^-1 + IB^-1 in world axes; dLambda = -K^-1 (wB - wA).
        /// </summary>
        public static void SolveFriction(float frictionTorque, ref Vector3 impulse, ref SolverBody a, ref SolverBody b, Vector3 axis, float h)
        {
            if (frictionTorque == 0) return;
            Vector3 dw = b.AngularVelocity - a.AngularVelocity;
            Mathematics.Mat3 k = a.InverseInertia + b.InverseInertia;
            Vector3 delta;
            if (axis != Vector3.Zero)
            {
                float kAxis = Vector3.Dot(axis, k * axis);
                delta = kAxis > 1e-30f ? (-Vector3.Dot(axis, dw) / kAxis) * axis : Vector3.Zero;
            }
            else if ((a.IsDynamic | b.IsDynamic) > 1) delta = -(AxisLockMath.InverseOnFreeAxes(k) * dw);
            else if (!k.TryInvert(out Mathematics.Mat3 mass)) return;
            else delta = -(mass * dw);
            Vector3 old = impulse;
            Vector3 total = old + delta;
            float max = frictionTorque * h;
            float len2 = total.LengthSquared();
            if (len2 > max * max) total *= max / MathF.Sqrt(len2);
            impulse = total;
            Vector3 applied = total - old;
            a.AngularVelocity -= a.InverseInertia * applied;
            b.AngularVelocity += b.InverseInertia * applied;
        }

        /// <summary>A spring toward C = 0: a soft row with the joint's own frequency and damping.</summary>
        public static void SolveSpring(ref AxisConstraintPart row, ref SolverBody a, ref SolverBody b, float C, in Softness soft)
        {
            float bias = soft.Bias(C, out float massScale, out float impulseScale);
            row.Solve(ref a, ref b, bias, massScale, impulseScale, float.NegativeInfinity, float.PositiveInfinity);
        }

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

        /// <summary>Writes the joint's reports: force and torque on B from this (sub)step's impulses, stress, position error.</summary>
        public static void Report(ref JointData j, in StepParameters p, Vector3 linearImpulse, Vector3 angularImpulse, float error)
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
