namespace Fulcrum.Components
{
    /// <summary>
    /// Unity's collision detection modes. Fulcrum has one continuous method (a sweep of the
    /// body against the world, <see cref="BodyDef.Ccd"/>), so every mode other than
    /// <see cref="Discrete"/> turns it on; the distinctions Unity draws between them
    /// (static-only sweeps, speculative margins) do not apply.
    /// </summary>
    public enum CollisionDetectionMode
    {
        /// <summary>No sweep: a fast thin object may tunnel.</summary>
        Discrete = 0,
        /// <summary>Continuous collision (BodyDef.Ccd).</summary>
        Continuous = 1,
        /// <summary>Continuous collision (BodyDef.Ccd); same as <see cref="Continuous"/> in Fulcrum.</summary>
        ContinuousDynamic = 2,
        /// <summary>Continuous collision (BodyDef.Ccd); same as <see cref="Continuous"/> in Fulcrum.</summary>
        ContinuousSpeculative = 3,
    }
}
