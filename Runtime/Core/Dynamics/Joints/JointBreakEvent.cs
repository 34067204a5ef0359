using System.Numerics;

namespace Fulcrum
{
    /// <summary>
    /// A joint broke in the last step because its force or torque went over its threshold. Read
    /// from <see cref="World.JointBreakEvents"/> after <see cref="World.Step"/>; the buffer is
    /// reused by the next step. The broken joint stays (inert) until it is destroyed, so its
    /// handle can still be queried.
    /// </summary>
    public struct JointBreakEvent
    {
        /// <summary>The joint.</summary>
        public JointHandle Joint;
        /// <summary>Its first body (None for the world).</summary>
        public BodyHandle BodyA;
        /// <summary>Its second body (None for the world).</summary>
        public BodyHandle BodyB;
        /// <summary>The constraint force on B when it broke, world, N.</summary>
        public Vector3 Force;
        /// <summary>The constraint torque on B when it broke, world, N m.</summary>
        public Vector3 Torque;
        /// <summary>max(|force| / BreakForce, |torque| / BreakTorque): above 1.</summary>
        public float Stress;
        /// <summary>The joint's <see cref="JointDef.UserData"/>.</summary>
        public ulong UserData;
    }
}
