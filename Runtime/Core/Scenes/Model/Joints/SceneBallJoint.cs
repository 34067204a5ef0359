namespace Fulcrum.Scenes
{
    /// <summary><c>{"type": "ball"}</c>: the two anchors coincide; rotation is free.</summary>
    public sealed class SceneBallJoint : SceneJoint
    {
        /// <inheritdoc/>
        public override JointKind Type => JointKind.Ball;
    }
}
