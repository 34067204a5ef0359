namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "hinge", "axisA", "axisB", "lowerDeg", "upperDeg", "motorSpeed", "maxMotorTorque"}</c>:
    /// anchors coincide and axis A (in A's frame) stays aligned with axis B (in B's frame).
    /// </summary>
    public sealed class SceneHingeJoint : SceneAxisPairJoint
    {
        /// <inheritdoc/>
        public override JointKind Type => JointKind.Hinge;

        /// <summary><c>lowerDeg</c>: lower angle limit, degrees, in [-180, 180]; null: no lower limit.</summary>
        public float? LowerDeg { get; set; }

        /// <summary><c>upperDeg</c>: upper angle limit, degrees, in [-180, 180], &gt;= lowerDeg; null: no upper limit.</summary>
        public float? UpperDeg { get; set; }

        /// <summary><c>motorSpeed</c>: target relative angular speed, rad/s. Default: 0.</summary>
        public float MotorSpeed { get; set; }

        /// <summary><c>maxMotorTorque</c>: the most torque the motor may apply, N m, &gt;= 0; 0 turns the motor off. Default: 0.</summary>
        public float MaxMotorTorque { get; set; }
    }
}
