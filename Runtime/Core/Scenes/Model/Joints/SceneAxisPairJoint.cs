using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// A joint with an axis in each body's frame, <c>axisA</c> and <c>axisB</c> (hinge, cone-twist):
    /// the two fields are read, checked and written the same way for every such kind.
    /// </summary>
    public abstract class SceneAxisPairJoint : SceneJoint
    {
        /// <summary><c>axisA</c>: the joint axis in A's frame (a hinge's axis, a cone's centre line), non-zero. Required.</summary>
        public Vector3 AxisA { get; set; }

        /// <summary><c>axisB</c>: the joint axis in B's frame (a hinge's axis, the twist axis), non-zero. Required.</summary>
        public Vector3 AxisB { get; set; }
    }
}
