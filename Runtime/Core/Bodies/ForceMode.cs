namespace Fulcrum
{
    /// <summary>How a vector given to AddForce/AddTorque is applied; the same four modes as Unity.</summary>
    public enum ForceMode : byte
    {
        /// <summary>A force in newtons (torque in N m), accumulated and applied over the next step.</summary>
        Force = 0,
        /// <summary>An acceleration in m/s^2 (rad/s^2), mass-independent, applied over the next step.</summary>
        Acceleration = 1,
        /// <summary>An impulse in N s (N m s), applied to the velocity at once.</summary>
        Impulse = 2,
        /// <summary>A velocity change in m/s (rad/s), mass-independent, applied at once.</summary>
        VelocityChange = 3,
    }
}
