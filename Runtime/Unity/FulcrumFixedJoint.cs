#nullable enable
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>Holds two bodies (or a body and the world) in their relative pose at enable time (Unity's FixedJoint).</summary>
    public sealed class FulcrumFixedJoint : FulcrumJoint
    {
        /// <inheritdoc/>
        protected override F.Joint Create(F.Entity shadow) => shadow.AddComponent<F.FixedJoint>();

        /// <inheritdoc/>
        protected override void PushKind(F.Joint j) { }
    }
}
