namespace Fulcrum.Components
{
    /// <summary>How a <see cref="Rigidbody"/>'s transform is shown between fixed steps, as in Unity.</summary>
    public enum RigidbodyInterpolation
    {
        /// <summary>The transform shows the pose of the last step (it moves in jumps when frames and steps differ).</summary>
        None = 0,
        /// <summary>The transform blends the last two step poses (smooth, one step behind).</summary>
        Interpolate = 1,
        /// <summary>The transform predicts from the last pose and velocity (smooth, can overshoot on impact).</summary>
        Extrapolate = 2,
    }
}
