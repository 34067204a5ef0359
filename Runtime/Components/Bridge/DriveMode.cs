namespace Fulcrum.Components
{
    /// <summary>Who moves a bridged entity.</summary>
    public enum DriveMode : byte
    {
        /// <summary>The simulation moves it (a dynamic body); <see cref="PhysicsBridge.SyncToGame"/> writes its pose to the entity.</summary>
        Physics = 0,
        /// <summary>
        /// The game moves it; <see cref="PhysicsBridge.SyncFromGame"/> reads its pose and the body
        /// (kinematic) follows with the velocity that reaches it, so it pushes dynamic bodies.
        /// A static body registered this way never moves.
        /// </summary>
        Game = 1,
    }
}
