namespace Fulcrum.Components
{
    /// <summary>Welds this body to the connected one (or the world) in their pose at build time (Unity's FixedJoint).</summary>
    public sealed class FixedJoint : Joint
    {
        internal override void Configure(ref JointDef def) => def.Kind = JointKind.Fixed;
    }
}
