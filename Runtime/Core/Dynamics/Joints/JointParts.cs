using System.Runtime.InteropServices;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The constraint parts of a joint with their accumulated impulses: one block per kind,
    /// overlaid (a joint's kind never changes, and only its own block is read or written), so a
    /// <see cref="JointData"/> is as large as its largest kind rather than all kinds together.
    /// Every block holds only unmanaged fields, as an explicit layout needs on every runtime.
    /// </summary>
    [StructLayout(LayoutKind.Explicit)]
    internal struct JointParts
    {
        [FieldOffset(0)] public BallJointParts Ball;
        [FieldOffset(0)] public HingeJointParts Hinge;
        [FieldOffset(0)] public DistanceJointParts Distance;
        [FieldOffset(0)] public FixedJointParts Fixed;
        [FieldOffset(0)] public PrismaticJointParts Prismatic;
        [FieldOffset(0)] public ConeTwistJointParts ConeTwist;
    }
}
