namespace Fulcrum.Scenes
{
    /// <summary><c>{"type": "fixed"}</c>: the bodies keep their relative pose at creation.</summary>
    public sealed class SceneFixedJoint : SceneJoint
    {
        /// <inheritdoc/>
        public override JointKind Type => JointKind.Fixed;
    }
}
