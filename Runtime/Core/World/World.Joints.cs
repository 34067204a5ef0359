using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Dynamics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        internal JointStorage Joints = new JointStorage();
        JointBreakEvent[] _jointBreaks = new JointBreakEvent[4];
        int _jointBreakCount;

        /// <summary>Live joints (broken ones included until destroyed).</summary>
        public int JointCount => Joints.ActiveCount;

        /// <summary>The joints that broke in the last step; valid until the next step.</summary>
        public ReadOnlySpan<JointBreakEvent> JointBreakEvents => new ReadOnlySpan<JointBreakEvent>(_jointBreaks, 0, _jointBreakCount);

        /// <summary>
        /// Creates a joint. Every field of <paramref name="def"/> is checked before anything
        /// changes: a stale body handle throws <see cref="StaleHandleException"/>; a joint between
        /// a body and itself, a non-finite anchor or axis, limits with min &gt; max or breaking
        /// thresholds &lt;= 0 throw an <see cref="ArgumentException"/> naming the field. The joint
        /// takes the bodies' current relative pose as its rest pose, and wakes both bodies.
        /// </summary>
        public JointHandle CreateJoint(in JointDef def)
        {
            ThrowIfInStep();
            if (def.Kind > JointKind.ConeTwist) throw new ArgumentException($"joint.Kind {def.Kind} is not a joint kind.", "joint.Kind");
            int a = def.BodyA.IsNone ? -1 : Slot(def.BodyA);
            int b = def.BodyB.IsNone ? -1 : Slot(def.BodyB);
            if (a < 0 && b < 0) throw new ArgumentException("joint.BodyB: a joint needs at least one body; both ends are the world.", "joint.BodyB");
            if (a == b) throw new ArgumentException($"joint.BodyB must differ from joint.BodyA: a joint between {Describe(a)} and itself.", "joint.BodyB");
            Limits.CheckPosition(def.AnchorA, "joint.AnchorA");
            Limits.CheckPosition(def.AnchorB, "joint.AnchorB");
            bool usesAxisA = def.Kind == JointKind.Hinge || def.Kind == JointKind.Prismatic || def.Kind == JointKind.ConeTwist || def.Kind == JointKind.Fixed;
            bool usesAxisB = def.Kind == JointKind.Hinge || def.Kind == JointKind.ConeTwist;
            if (usesAxisA) Direction(def.AxisA, "joint.AxisA");
            if (usesAxisB) Direction(def.AxisB, "joint.AxisB");
            CheckJointNumbers(def);

            JointData j = default;
            j.Kind = def.Kind;
            j.BodyA = a;
            j.BodyB = b;
            j.LocalAnchorA = def.AnchorA;
            j.LocalAnchorB = def.AnchorB;
            Quaternion qA = a < 0 ? Quaternion.Identity : Bodies.Rotation[a];
            Quaternion qB = b < 0 ? Quaternion.Identity : Bodies.Rotation[b];
            j.LocalFrameA = FrameAlong(Vector3.Normalize(usesAxisA ? def.AxisA : Vector3.UnitX));
            Quaternion worldA = qA * j.LocalFrameA;
            j.LocalFrameB = usesAxisB
                ? FrameMatching(Vector3.Normalize(def.AxisB), Quaternion.Conjugate(qB) * worldA)
                : Quaternion.Normalize(Quaternion.Conjugate(qB) * worldA);
            const float toRad = MathF.PI / 180f;
            if (def.Kind == JointKind.Hinge)
            {
                j.Lower = def.LowerDeg * toRad;
                j.Upper = def.UpperDeg * toRad;
                j.MaxMotorForce = def.MaxMotorTorque;
            }
            else if (def.Kind == JointKind.Prismatic)
            {
                j.Lower = def.Lower;
                j.Upper = def.Upper;
                j.MaxMotorForce = def.MaxMotorForce;
            }
            j.MotorSpeed = def.MotorSpeed;
            bool turns = def.Kind == JointKind.Ball || def.Kind == JointKind.Hinge || def.Kind == JointKind.ConeTwist;
            j.FrictionTorque = turns ? def.FrictionTorque : 0;
            j.SpringHertz = def.Kind == JointKind.Hinge || def.Kind == JointKind.Distance ? def.StiffnessHz : 0;
            j.SpringDamping = def.Damping;
            j.ConeAngle = def.Kind == JointKind.ConeTwist ? def.ConeDeg * toRad : MathF.PI;
            j.TwistAngle = def.Kind == JointKind.ConeTwist ? def.TwistDeg * toRad : MathF.PI;
            if (def.Kind == JointKind.Distance) DistanceLimits(def, a, b, ref j);
            j.BreakForce = def.BreakForce;
            j.BreakTorque = def.BreakTorque;
            j.CollideConnected = def.CollideConnected;
            j.UserData = def.UserData;
            j.SolverA = j.SolverB = -1;

            Joints.EnsureBodies(Bodies.SlotCount);
            int slot = Joints.Allocate();
            Joints.Data[slot] = j;
            Joints.Name[slot] = def.Name;
            Joints.Link(slot);
            if (!def.CollideConnected && a >= 0 && b >= 0) DestroyContactsBetween(a, b);
            if (a >= 0) Wake(a);
            if (b >= 0) Wake(b);
            return new JointHandle(slot, Joints.Generation[slot], Id);
        }

        static void Direction(Vector3 v, string name)
        {
            Validate.Finite(v, name);
            if (!(v.LengthSquared() > 1e-12f)) throw new ArgumentException($"{name} must be a non-zero direction, got {v}.", name);
            // Normalising squares the components: 1e20 would overflow to infinity and give NaN.
            if (float.IsInfinity(v.LengthSquared())) throw new ArgumentException($"{name} is too long to normalise in single precision (components up to about 1e18), got {v}.", name);
        }

        // A motor's target speed and strength within the input limits (Limits.MaxInputSpeed, Limits.MaxForce).
        static void CheckMotor(float speed, float max, string speedName, string maxName)
        {
            if (Math.Abs(speed) > Limits.MaxInputSpeed)
                throw new ArgumentException($"{speedName} must be within +-{Limits.MaxInputSpeed:G} (Limits.MaxInputSpeed), got {speed}.", speedName);
            if (max > Limits.MaxForce && !float.IsPositiveInfinity(max))
                throw new ArgumentException($"{maxName} must be at most {Limits.MaxForce:G} (Limits.MaxForce) or infinity, got {max}.", maxName);
        }

        static void CheckJointNumbers(in JointDef d)
        {
            NotNaN(d.LowerDeg, "joint.LowerDeg");
            NotNaN(d.UpperDeg, "joint.UpperDeg");
            if (d.Kind == JointKind.Hinge)
            {
                if (d.LowerDeg > d.UpperDeg) throw new ArgumentException($"joint.LowerDeg ({d.LowerDeg}) must not exceed joint.UpperDeg ({d.UpperDeg}).", "joint.LowerDeg");
                if (float.IsFinite(d.LowerDeg) && d.LowerDeg < -180f) throw new ArgumentException($"joint.LowerDeg must be in [-180, 180], got {d.LowerDeg}.", "joint.LowerDeg");
                if (float.IsFinite(d.UpperDeg) && d.UpperDeg > 180f) throw new ArgumentException($"joint.UpperDeg must be in [-180, 180], got {d.UpperDeg}.", "joint.UpperDeg");
            }
            Validate.Finite(d.MotorSpeed, "joint.MotorSpeed");
            Validate.NonNegative(d.MaxMotorTorque, "joint.MaxMotorTorque");
            Validate.NonNegative(d.MaxMotorForce, "joint.MaxMotorForce");
            CheckMotor(d.MotorSpeed, Math.Max(d.MaxMotorTorque, d.MaxMotorForce), "joint.MotorSpeed", "joint.MaxMotorTorque");
            Validate.NonNegative(d.FrictionTorque, "joint.FrictionTorque");
            NotNaN(d.MinLength, "joint.MinLength");
            NotNaN(d.MaxLength, "joint.MaxLength");
            NotNaN(d.RestLength, "joint.RestLength");
            if (float.IsPositiveInfinity(d.MinLength)) throw new ArgumentException("joint.MinLength must be finite.", "joint.MinLength");
            if (float.IsPositiveInfinity(d.RestLength)) throw new ArgumentException("joint.RestLength must be finite.", "joint.RestLength");
            if (d.Kind == JointKind.Distance && d.MinLength >= 0 && d.MaxLength >= 0 && d.MinLength > d.MaxLength)
                throw new ArgumentException($"joint.MinLength ({d.MinLength}) must not exceed joint.MaxLength ({d.MaxLength}).", "joint.MinLength");
            Validate.NonNegative(d.StiffnessHz, "joint.StiffnessHz");
            Validate.NonNegative(d.Damping, "joint.Damping");
            NotNaN(d.Lower, "joint.Lower");
            NotNaN(d.Upper, "joint.Upper");
            if (d.Kind == JointKind.Prismatic && d.Lower > d.Upper)
                throw new ArgumentException($"joint.Lower ({d.Lower}) must not exceed joint.Upper ({d.Upper}).", "joint.Lower");
            if (!(d.ConeDeg >= 0 && d.ConeDeg <= 180)) throw new ArgumentException($"joint.ConeDeg must be in [0, 180], got {d.ConeDeg}.", "joint.ConeDeg");
            if (!(d.TwistDeg >= 0 && d.TwistDeg <= 180)) throw new ArgumentException($"joint.TwistDeg must be in [0, 180], got {d.TwistDeg}.", "joint.TwistDeg");
            if (!(d.BreakForce > 0)) throw new ArgumentException($"joint.BreakForce must be > 0 (+infinity = unbreakable), got {d.BreakForce}.", "joint.BreakForce");
            if (!(d.BreakTorque > 0)) throw new ArgumentException($"joint.BreakTorque must be > 0 (+infinity = unbreakable), got {d.BreakTorque}.", "joint.BreakTorque");
        }

        static void NotNaN(float v, string name)
        {
            if (float.IsNaN(v)) throw new ArgumentException($"{name} must be a number, got NaN.", name);
        }

        // Unset limits: none at all makes a rod at the current length (or a free spring);
        // one of the two leaves the other side open.
        void DistanceLimits(in JointDef def, int a, int b, ref JointData j)
        {
            Vector3 pA = a < 0 ? def.AnchorA : new Pose(Bodies.Position[a], Bodies.Rotation[a]).TransformPoint(def.AnchorA);
            Vector3 pB = b < 0 ? def.AnchorB : new Pose(Bodies.Position[b], Bodies.Rotation[b]).TransformPoint(def.AnchorB);
            float length = Vector3.Distance(pA, pB);
            bool hasMin = def.MinLength >= 0, hasMax = def.MaxLength >= 0;
            if (!hasMin && !hasMax)
            {
                j.MinLength = def.StiffnessHz > 0 ? 0 : length;
                j.MaxLength = def.StiffnessHz > 0 ? float.PositiveInfinity : length;
            }
            else
            {
                j.MinLength = hasMin ? def.MinLength : 0;
                j.MaxLength = hasMax ? def.MaxLength : float.PositiveInfinity;
            }
            j.RestLength = def.RestLength >= 0 ? def.RestLength : Math.Clamp(length, j.MinLength, j.MaxLength);
        }

        // The joint frame whose x axis is the given unit axis (y, z from the normal's tangent basis).
        static Quaternion FrameAlong(Vector3 axis)
        {
            TangentBasis.Build(axis, out Vector3 t1, out Vector3 t2);
            return Rotation.FromMatrix(new Mat3(axis, t1, t2));
        }

        // B's joint frame: x along B's own axis, y as close as possible to A's frame's y (both
        // seen in B's frame), so the hinge angle and the twist start at zero.
        static Quaternion FrameMatching(Vector3 axisB, Quaternion frameAInB)
        {
            Vector3 y = Vector3.Transform(Vector3.UnitY, frameAInB);
            y -= Vector3.Dot(y, axisB) * axisB;
            if (y.LengthSquared() < 1e-8f)
            {
                y = Vector3.Transform(Vector3.UnitZ, frameAInB);
                y -= Vector3.Dot(y, axisB) * axisB;
            }
            y = Vector3.Normalize(y);
            return Rotation.FromMatrix(new Mat3(axisB, y, Vector3.Cross(axisB, y)));
        }

        // Jointed bodies stop colliding at once: their existing contacts go (with end events);
        // the broad phase's pair filter keeps new ones from forming.
        void DestroyContactsBetween(int a, int b)
        {
            ContactGraph g = ContactGraph;
            for (int s = Bodies.FirstShape[a]; s >= 0; s = Shapes.NextInBody[s])
            {
                int e = g.FirstEdge(s);
                while (e >= 0)
                {
                    int next = g.NextEdge(e);
                    int c = e >> 1;
                    ref Contact ct = ref g.Contacts[c];
                    if ((ct.BodyA == b || ct.BodyB == b) && (ct.Flags & ContactFlags.Sensor) == 0)
                    {
                        if ((ct.Flags & ContactFlags.Touching) != 0) RecordRemovalEnd(c);
                        g.Destroy(c);
                    }
                    e = next;
                }
            }
        }

        /// <summary>Removes a joint and wakes its bodies. The handle goes stale.</summary>
        public void DestroyJoint(JointHandle joint)
        {
            ThrowIfInStep();
            int slot = JointSlot(joint);
            ReleaseJoint(slot);
        }

        void ReleaseJoint(int slot)
        {
            ref JointData j = ref Joints.Data[slot];
            if (j.BodyA >= 0) Wake(j.BodyA);
            if (j.BodyB >= 0) Wake(j.BodyB);
            Joints.Release(slot);
        }

        void DestroyJointsOf(int body)
        {
            if (body >= Joints.FirstEdge.Length) return;
            while (Joints.FirstEdge[body] >= 0) ReleaseJoint(Joints.FirstEdge[body] >> 1);
        }

        /// <summary>True when the handle names a live joint of this world.</summary>
        public bool IsValid(JointHandle joint) => joint.WorldId == Id && Joints.IsLive(joint);

        internal int JointSlot(JointHandle joint) => LiveSlot(joint.Id, Joints.Slots, nameof(JointHandle), "joint", "destroyed");

        /// <summary>The kind of a joint.</summary>
        public JointKind GetJointKind(JointHandle joint) => Joints.Data[JointSlot(joint)].Kind;

        /// <summary>The joint's name, or null.</summary>
        public string? GetJointName(JointHandle joint) => Joints.Name[JointSlot(joint)];

        /// <summary>The constraint force the joint applied to its body B in the last step, world, N (A feels the opposite).</summary>
        public Vector3 GetJointForce(JointHandle joint) => Joints.Data[JointSlot(joint)].Force;

        /// <summary>The constraint torque the joint applied to its body B in the last step, world, N m.</summary>
        public Vector3 GetJointTorque(JointHandle joint) => Joints.Data[JointSlot(joint)].Torque;

        /// <summary>
        /// How close the joint came to breaking in the last step: max(|force| / BreakForce,
        /// |torque| / BreakTorque); 0 for an unbreakable joint, &gt; 1 once it broke.
        /// </summary>
        public float GetJointStress(JointHandle joint) => Joints.Data[JointSlot(joint)].Stress;

        /// <summary>The joint's position error after the last step (anchor gap, or length/slide outside its limits), m.</summary>
        public float GetJointError(JointHandle joint) => Joints.Data[JointSlot(joint)].Error;

        /// <summary>True once the joint broke; a broken joint no longer acts.</summary>
        public bool IsJointBroken(JointHandle joint) => Joints.Data[JointSlot(joint)].Broken;

        /// <summary>
        /// The hinge angle of B relative to A about the hinge axis (rad, 0 at creation), or the
        /// twist of a cone-twist joint; 0 for other kinds.
        /// </summary>
        public float GetJointAngle(JointHandle joint)
        {
            ref JointData j = ref Joints.Data[JointSlot(joint)];
            if (j.Kind != JointKind.Hinge && j.Kind != JointKind.ConeTwist) return 0;
            Quaternion qA = j.BodyA < 0 ? Quaternion.Identity : Bodies.Rotation[j.BodyA];
            Quaternion qB = j.BodyB < 0 ? Quaternion.Identity : Bodies.Rotation[j.BodyB];
            return JointSolver.TwistAngle(qA * j.LocalFrameA, qB * j.LocalFrameB);
        }

        /// <summary>
        /// Sets the motor of a hinge (speed rad/s, max torque N m) or prismatic joint (speed m/s,
        /// max force N); a max of 0 turns the motor off. Wakes the bodies.
        /// </summary>
        public void SetJointMotor(JointHandle joint, float speed, float maxForceOrTorque)
        {
            ThrowIfInStep();
            int slot = JointSlot(joint);
            Validate.Finite(speed, nameof(speed));
            Validate.NonNegative(maxForceOrTorque, nameof(maxForceOrTorque));
            CheckMotor(speed, maxForceOrTorque, nameof(speed), nameof(maxForceOrTorque));
            ref JointData j = ref Joints.Data[slot];
            if (j.Kind != JointKind.Hinge && j.Kind != JointKind.Prismatic)
                throw new InvalidOperationException($"A {j.Kind} joint has no motor.");
            j.MotorSpeed = speed;
            j.MaxMotorForce = maxForceOrTorque;
            if (j.BodyA >= 0) Wake(j.BodyA);
            if (j.BodyB >= 0) Wake(j.BodyB);
        }

        /// <summary>
        /// True when a joint between the two body slots asks that they not collide (the
        /// default: jointed bodies, such as a ragdoll's limbs, pass through each other).
        /// </summary>
        internal bool JointBlocksCollision(int bodyA, int bodyB)
        {
            if (bodyA >= Joints.FirstEdge.Length || bodyB >= Joints.FirstEdge.Length) return false;
            for (int e = Joints.FirstEdge[bodyA]; e >= 0; e = Joints.NextEdge[e])
            {
                ref JointData j = ref Joints.Data[e >> 1];
                int other = (e & 1) == 0 ? j.BodyB : j.BodyA;
                if (other == bodyB && !j.CollideConnected && !j.Broken) return true;
            }
            return false;
        }
    }
}
