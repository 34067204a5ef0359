using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// A joint's current geometry within the step, rebuilt for every pass from the bodies'
    /// motion since the start of the step: arms rA = dqA rA0, rB = dqB rB0, the anchor gap
    /// d = (cB + rB) - (cA + rA) and the world joint frames dqA fA0, dqB fB0.
    /// </summary>
    internal readonly struct JointGeometry
    {
        /// <summary>Anchor arms from the centres of mass, world.</summary>
        public readonly Vector3 ArmA, ArmB;
        /// <summary>Anchor gap (B's anchor minus A's), world.</summary>
        public readonly Vector3 Gap;
        /// <summary>World joint frames.</summary>
        public readonly Quaternion FrameA, FrameB;

        public JointGeometry(in JointData j, in SolverBody a, in SolverBody b)
        {
            ArmA = a.RotateByDelta(j.ArmA);
            ArmB = b.RotateByDelta(j.ArmB);
            Gap = (b.DeltaPosition - a.DeltaPosition) + j.DeltaCenter + ArmB - ArmA;
            FrameA = a.DeltaRotation * j.FrameA;
            FrameB = b.DeltaRotation * j.FrameB;
        }
    }
}
