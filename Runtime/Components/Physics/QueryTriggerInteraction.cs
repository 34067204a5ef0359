namespace Fulcrum.Components
{
    /// <summary>Whether a query sees trigger colliders (Unity's QueryTriggerInteraction).</summary>
    public enum QueryTriggerInteraction
    {
        /// <summary>Follow <see cref="PhysicsScene.queriesHitTriggers"/>.</summary>
        UseGlobal = 0,
        /// <summary>Triggers are not reported.</summary>
        Ignore = 1,
        /// <summary>Triggers are reported.</summary>
        Collide = 2,
    }
}
