namespace Fulcrum.Components
{
    /// <summary>
    /// Receives a <see cref="PhysicsBridge"/>'s contact and trigger events on the game thread,
    /// after the step that produced them. Registering, unregistering and forces requested from
    /// inside <see cref="OnContact"/> are deferred until the batch has been delivered.
    /// </summary>
    public interface IBridgeContactListener
    {
        /// <summary>One event; the reference is valid only during the call.</summary>
        void OnContact(in BridgeContact contact);
    }
}
