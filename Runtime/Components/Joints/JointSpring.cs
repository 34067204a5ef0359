using System;

namespace Fulcrum.Components
{
    /// <summary>A hinge spring in Unity's units (Unity's JointSpring).</summary>
    [Serializable]
    public struct JointSpring
    {
        /// <summary>Stiffness, N m per radian of angle from <see cref="targetPosition"/> (&gt;= 0).</summary>
        public float spring;
        /// <summary>Damping, N m s per radian (&gt;= 0).</summary>
        public float damper;
        /// <summary>The angle the spring pulls toward, degrees (the hinge <see cref="HingeJoint.angle"/>, 0 at the build pose).</summary>
        public float targetPosition;
    }
}
