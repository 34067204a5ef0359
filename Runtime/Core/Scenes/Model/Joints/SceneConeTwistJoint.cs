namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "coneTwist", "axisA", "axisB", "coneDeg", "twistDeg"}</c>: a ball joint whose
    /// axis B may swing at most coneDeg away from axis A and twist about it at most twistDeg
    /// either way (a shoulder, a rag-doll limb).
    /// </summary>
    public sealed class SceneConeTwistJoint : SceneAxisPairJoint
    {
        /// <inheritdoc/>
        public override JointKind Type => JointKind.ConeTwist;

        /// <summary><c>coneDeg</c>: the swing limit, degrees, in [0, 180]. Required.</summary>
        public float ConeDeg { get; set; }

        /// <summary><c>twistDeg</c>: the twist limit either way, degrees, in [0, 180]. Required.</summary>
        public float TwistDeg { get; set; }
    }
}
