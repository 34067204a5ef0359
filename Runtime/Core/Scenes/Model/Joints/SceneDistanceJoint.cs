namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "distance", "minLength", "maxLength", "stiffnessHz", "damping"}</c>: the
    /// distance between the anchors stays in [minLength, maxLength] (a rope: 0 to L; a rod:
    /// L to L). A missing length is the anchors' distance when the scene is built.
    /// </summary>
    public sealed class SceneDistanceJoint : SceneJoint
    {
        /// <inheritdoc/>
        public override JointKind Type => JointKind.Distance;

        /// <summary><c>minLength</c>, m, &gt;= 0; null: the initial distance.</summary>
        public float? MinLength { get; set; }

        /// <summary><c>maxLength</c>, m, &gt;= minLength; null: the initial distance.</summary>
        public float? MaxLength { get; set; }

        /// <summary><c>stiffnessHz</c>: spring frequency, Hz, &gt;= 0; 0 makes the limits rigid. Default: 0.</summary>
        public float StiffnessHz { get; set; }

        /// <summary><c>damping</c>: damping ratio of the spring (1 = critical), &gt;= 0. Default: 0.</summary>
        public float Damping { get; set; }
    }
}
