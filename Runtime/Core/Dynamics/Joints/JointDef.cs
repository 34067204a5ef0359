using System.Numerics;

namespace Fulcrum
{
    /// <summary>
    /// Everything needed to create a joint, one struct for every <see cref="JointKind"/>: a
    /// kind reads only its own fields. Start from <see cref="Default"/> or a factory
    /// (<see cref="Ball"/>, <see cref="Hinge"/>, ...). The fields carry the scene file's joint
    /// fields one to one (anchors in each body's local frame, relative to the body origin; a
    /// <see cref="BodyHandle.None"/> body is the world and its anchor a world point; angles in
    /// degrees where the name ends in Deg). At creation the joint takes the bodies' current
    /// relative pose as its rest pose (hinge angle 0, cone and twist measured from it).
    /// </summary>
    public struct JointDef
    {
        /// <summary>The kind. Default: <see cref="JointKind.Ball"/>.</summary>
        public JointKind Kind;
        /// <summary>First body; <see cref="BodyHandle.None"/> = the world. Default: None.</summary>
        public BodyHandle BodyA;
        /// <summary>Second body; <see cref="BodyHandle.None"/> = the world. Default: None.</summary>
        public BodyHandle BodyB;
        /// <summary>Anchor in A's local frame (a world point when A is the world), m. Default: 0.</summary>
        public Vector3 AnchorA;
        /// <summary>Anchor in B's local frame (a world point when B is the world), m. Default: 0.</summary>
        public Vector3 AnchorB;
        /// <summary>Hinge, prismatic (slide) and cone-twist (twist) axis in A's local frame. Default: +x.</summary>
        public Vector3 AxisA;
        /// <summary>Hinge and cone-twist axis in B's local frame. Default: +x.</summary>
        public Vector3 AxisB;
        /// <summary>Hinge: lower angle limit, degrees in [-180, 180]; -infinity = none. Default: -infinity.</summary>
        public float LowerDeg;
        /// <summary>Hinge: upper angle limit, degrees in [-180, 180]; +infinity = none. Default: +infinity.</summary>
        public float UpperDeg;
        /// <summary>Hinge (rad/s about the axis, B relative to A) or prismatic (m/s) motor speed. Default: 0.</summary>
        public float MotorSpeed;
        /// <summary>Hinge: the largest motor torque, N m; 0 = no motor. Default: 0.</summary>
        public float MaxMotorTorque;
        /// <summary>Prismatic: the largest motor force, N; 0 = no motor. Default: 0.</summary>
        public float MaxMotorForce;
        /// <summary>
        /// Distance: the shortest allowed distance between the anchors, m. Negative (the default,
        /// -1) means the distance at creation, or no lower limit when <see cref="StiffnessHz"/> &gt; 0.
        /// </summary>
        public float MinLength;
        /// <summary>
        /// Distance: the longest allowed distance, m (+infinity allowed: no upper limit). Negative
        /// (the default, -1) means the distance at creation, or no upper limit when <see cref="StiffnessHz"/> &gt; 0.
        /// Equal limits make a rigid rod; [0, L] a rope.
        /// </summary>
        public float MaxLength;
        /// <summary>Distance: the spring's rest length, m; negative = the distance at creation. Default: -1.</summary>
        public float RestLength;
        /// <summary>
        /// Spring frequency, Hz (distance: toward <see cref="RestLength"/>; hinge: toward the angle at
        /// creation); 0 = no spring. Default: 0.
        /// </summary>
        public float StiffnessHz;
        /// <summary>Spring damping ratio (1 = critical). Default: 0.</summary>
        public float Damping;
        /// <summary>
        /// Ball, hinge and cone-twist: joint friction, the largest torque that resists the
        /// bodies' relative rotation (about the hinge axis; about any axis for ball and
        /// cone-twist), N m. Without it a limb resting at a limit or hanging from one swings
        /// as an undamped pendulum and never sleeps; ragdolls want a little. Default: 0.
        /// </summary>
        public float FrictionTorque;
        /// <summary>Prismatic: lower limit of the slide, m; -infinity = none. Default: -infinity.</summary>
        public float Lower;
        /// <summary>Prismatic: upper limit of the slide, m; +infinity = none. Default: +infinity.</summary>
        public float Upper;
        /// <summary>Cone-twist: half-angle of the swing cone, degrees in [0, 180]; 180 = free. Default: 180.</summary>
        public float ConeDeg;
        /// <summary>Cone-twist: twist limit either way about the twist axis, degrees in [0, 180]; 180 = free. Default: 180.</summary>
        public float TwistDeg;
        /// <summary>The force (N) above which the joint breaks; must be &gt; 0. Default: +infinity (unbreakable).</summary>
        public float BreakForce;
        /// <summary>The torque (N m) above which the joint breaks; must be &gt; 0. Default: +infinity.</summary>
        public float BreakTorque;
        /// <summary>Whether the two bodies still collide with each other. Default: false.</summary>
        public bool CollideConnected;
        /// <summary>A name for errors and debugging. Default: null.</summary>
        public string? Name;
        /// <summary>Free for the user; carried into <see cref="JointBreakEvent"/>. Default: 0.</summary>
        public ulong UserData;

        /// <summary>A ball joint between the world and the world (set the bodies) with the defaults documented on each field.</summary>
        public static JointDef Default => new JointDef
        {
            Kind = JointKind.Ball,
            AxisA = Vector3.UnitX,
            AxisB = Vector3.UnitX,
            LowerDeg = float.NegativeInfinity,
            UpperDeg = float.PositiveInfinity,
            MinLength = -1,
            MaxLength = -1,
            RestLength = -1,
            Lower = float.NegativeInfinity,
            Upper = float.PositiveInfinity,
            ConeDeg = 180,
            TwistDeg = 180,
            BreakForce = float.PositiveInfinity,
            BreakTorque = float.PositiveInfinity,
        };

        static JointDef Of(JointKind kind, BodyHandle a, BodyHandle b, Vector3 anchorA, Vector3 anchorB)
        {
            JointDef d = Default;
            d.Kind = kind;
            d.BodyA = a;
            d.BodyB = b;
            d.AnchorA = anchorA;
            d.AnchorB = anchorB;
            return d;
        }

        /// <summary>A ball joint.</summary>
        public static JointDef Ball(BodyHandle a, BodyHandle b, Vector3 anchorA, Vector3 anchorB) =>
            Of(JointKind.Ball, a, b, anchorA, anchorB);

        /// <summary>A hinge about <paramref name="axisA"/> (A's frame) = <paramref name="axisB"/> (B's frame), free unless limits are set.</summary>
        public static JointDef Hinge(BodyHandle a, BodyHandle b, Vector3 anchorA, Vector3 anchorB, Vector3 axisA, Vector3 axisB)
        {
            JointDef d = Of(JointKind.Hinge, a, b, anchorA, anchorB);
            d.AxisA = axisA;
            d.AxisB = axisB;
            return d;
        }

        /// <summary>A distance joint kept within [<paramref name="minLength"/>, <paramref name="maxLength"/>].</summary>
        public static JointDef Distance(BodyHandle a, BodyHandle b, Vector3 anchorA, Vector3 anchorB, float minLength, float maxLength)
        {
            JointDef d = Of(JointKind.Distance, a, b, anchorA, anchorB);
            d.MinLength = minLength;
            d.MaxLength = maxLength;
            return d;
        }

        /// <summary>A weld holding the bodies' current relative pose.</summary>
        public static JointDef Fixed(BodyHandle a, BodyHandle b, Vector3 anchorA, Vector3 anchorB) =>
            Of(JointKind.Fixed, a, b, anchorA, anchorB);

        /// <summary>A slider along <paramref name="axisA"/> (A's frame).</summary>
        public static JointDef Prismatic(BodyHandle a, BodyHandle b, Vector3 anchorA, Vector3 anchorB, Vector3 axisA)
        {
            JointDef d = Of(JointKind.Prismatic, a, b, anchorA, anchorB);
            d.AxisA = axisA;
            return d;
        }

        /// <summary>A cone-twist joint with twist axes <paramref name="axisA"/>/<paramref name="axisB"/> and the given limits (degrees).</summary>
        public static JointDef ConeTwist(BodyHandle a, BodyHandle b, Vector3 anchorA, Vector3 anchorB, Vector3 axisA, Vector3 axisB, float coneDeg, float twistDeg)
        {
            JointDef d = Of(JointKind.ConeTwist, a, b, anchorA, anchorB);
            d.AxisA = axisA;
            d.AxisB = axisB;
            d.ConeDeg = coneDeg;
            d.TwistDeg = twistDeg;
            return d;
        }
    }
}
