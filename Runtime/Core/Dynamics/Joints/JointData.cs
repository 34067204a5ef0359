using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// One joint: a common header (kind, bodies, anchors, frames, the definition in solver
    /// units: radians, metres, newtons; the per-step geometry; what it reports) and its kind's
    /// constraint parts, overlaid on the other kinds' (<see cref="Parts"/>; each kind's solver,
    /// <c>&lt;Kind&gt;JointSolver</c>, says what its parts are). Blittable: names live beside it
    /// in <see cref="JointStorage"/>.
    /// </summary>
    internal struct JointData
    {
        public JointKind Kind;
        /// <summary>Body slots; -1 is the world.</summary>
        public int BodyA, BodyB;
        /// <summary>Anchors in the bodies' frames, relative to the body origins (world points for the world).</summary>
        public Vector3 LocalAnchorA, LocalAnchorB;
        /// <summary>Joint frames in the bodies' frames; their x axis is the joint axis.</summary>
        public Quaternion LocalFrameA, LocalFrameB;
        /// <summary>Hinge limits (rad) or prismatic limits (m).</summary>
        public float Lower, Upper;
        /// <summary>Distance limits and spring rest length, m.</summary>
        public float MinLength, MaxLength, RestLength;
        /// <summary>Cone-twist: swing cone half-angle and twist limit, rad.</summary>
        public float ConeAngle, TwistAngle;
        /// <summary>Motor speed (rad/s or m/s) and largest motor torque or force (N m or N); 0 = no motor.</summary>
        public float MotorSpeed, MaxMotorForce;
        /// <summary>Joint friction: the largest torque against relative rotation, N m (0 = none).</summary>
        public float FrictionTorque;
        /// <summary>Spring frequency (Hz, 0 = none) and damping ratio.</summary>
        public float SpringHertz, SpringDamping;
        /// <summary>The spring's coefficients over the current (sub)step.</summary>
        public Softness SpringSoftness;
        /// <summary>Breaking thresholds, N and N m (+infinity = unbreakable).</summary>
        public float BreakForce, BreakTorque;
        public bool CollideConnected;
        /// <summary>Broke over its threshold: inert until destroyed.</summary>
        public bool Broken;
        public ulong UserData;

        // Per step.
        /// <summary>Solver body indices (0 = fixed); -1 when the joint sits out this step.</summary>
        public int SolverA, SolverB;
        /// <summary>Anchor arms from the centres of mass at the start of the step, world.</summary>
        public Vector3 ArmA, ArmB;
        /// <summary>cB - cA at the start of the step.</summary>
        public Vector3 DeltaCenter;
        /// <summary>World joint frames at the start of the step.</summary>
        public Quaternion FrameA, FrameB;
        /// <summary>The (sub)step the impulses belong to, s.</summary>
        public float StepDt;
        /// <summary>
        /// The anchor rows (a rigid distance joint's length row, a prismatic joint's cross rows and
        /// lock) are solved by
        /// <see cref="JointTreeSolver"/> this step: the Gauss-Seidel velocity passes skip them (set
        /// every step by <see cref="JointTreeSolver.Build"/>).
        /// </summary>
        public bool DirectPoint;
        /// <summary>
        /// The rotation rows of a fixed or hinge joint are solved by <see cref="JointTreeSolver"/>
        /// this step (set with <see cref="DirectPoint"/>).
        /// </summary>
        public bool DirectRotation;
        /// <summary>
        /// A hinge's or slider's limit row solved by <see cref="JointTreeSolver"/> this step: +1 the
        /// lower limit it rests on or closes on, -1 the upper, 0 none (set with
        /// <see cref="DirectRotation"/>, or with <see cref="DirectPoint"/> for a slider). A cone-twist
        /// joint's bits: 1 its cone, 2 its lower twist limit, 4 its upper, 8 the block takes its
        /// limits as it meets them (set with <see cref="DirectPoint"/>, where the tree carries a heavy load).
        /// </summary>
        public sbyte DirectLimit;

        /// <summary>
        /// The kind's constraint parts with their accumulated impulses (kept from step to step
        /// for warm starting): one block per kind, overlaid (<see cref="JointParts"/>).
        /// </summary>
        public JointParts Parts;

        // Reports.
        /// <summary>Constraint force and torque on B in the last step, world, N and N m.</summary>
        public Vector3 Force, Torque;
        /// <summary>max(|F| / BreakForce, |T| / BreakTorque).</summary>
        public float Stress;
        /// <summary>Position error after the last step, m.</summary>
        public float Error;

        public readonly bool HasLowerLimit => Kind == JointKind.Hinge || Kind == JointKind.Prismatic ? Lower > float.NegativeInfinity
            : Kind == JointKind.Distance ? MinLength > 0 && MinLength < MaxLength
            : Kind == JointKind.ConeTwist && TwistAngle < System.MathF.PI;

        public readonly bool HasUpperLimit => Kind == JointKind.Hinge || Kind == JointKind.Prismatic ? Upper < float.PositiveInfinity
            : Kind == JointKind.Distance ? MaxLength < float.PositiveInfinity && MinLength < MaxLength
            : Kind == JointKind.ConeTwist && TwistAngle < System.MathF.PI;
    }
}
