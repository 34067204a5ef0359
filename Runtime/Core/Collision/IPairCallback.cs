namespace Fulcrum.Collision
{
    /// <summary>
    /// Receives the broad phase's new pairs of overlapping fat boxes (<see cref="BroadPhase.UpdatePairs{T}"/>).
    /// A struct implementing this is passed by reference as a generic argument, so the call is
    /// direct and allocates nothing.
    /// </summary>
    internal interface IPairCallback
    {
        /// <summary>
        /// Whether the pair of shapes <paramref name="shapeA"/> and <paramref name="shapeB"/> may
        /// become a contact. Reads only: the parallel pair search calls it from worker threads.
        /// </summary>
        bool Accepts(int shapeA, int shapeB);

        /// <summary>Called once per new overlap the callback accepted, in the order of the serial search (on the stepping thread).</summary>
        void AddPair(int shapeA, int shapeB);
    }
}
