using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "coneTwist", "axisA", "axisB", "coneDeg", "twistDeg"}</c>: a ball joint whose
    /// axis B may swing at most coneDeg away from axis A and twist about it at most twistDeg
    /// either way (a shoulder, a rag-doll limb).
    /// </summary>
    public sealed class SceneConeTwistJoint : SceneJoint
    {
        /// <inheritdoc/>
        public override JointKind Type => JointKind.ConeTwist;

        /// <summary><c>axisA</c>: the cone axis in A's frame, non-zero. Required.</summary>
        public Vector3 AxisA { get; set; }

        /// <summary><c>axisB</c>: the twist axis in B's frame, non-zero. Required.</summary>
        public Vector3 AxisB { get; set; }

        /// <summary><c>coneDeg</c>: the swing limit, degrees, in [0, 180]. Required.</summary>
        public float ConeDeg { get; set; }

        /// <summary><c>twistDeg</c>: the twist limit either way, degrees, in [0, 180]. Required.</summary>
        public float TwistDeg { get; set; }
    }
}
