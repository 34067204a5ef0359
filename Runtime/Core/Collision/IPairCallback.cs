namespace Fulcrum.Collision
{
    /// <summary>
    /// Receives the broad phase's new pairs of overlapping fat boxes (<see cref="BroadPhase.UpdatePairs{T}"/>).
    /// A struct implementing this is passed by reference as a generic argument, so the call is
    /// direct and allocates nothing.
    /// </summary>
    internal interface IPairCallback
    {
        /// <summary>Called once per new overlap of the fat boxes of shapes <paramref name="shapeA"/> and <paramref name="shapeB"/>.</summary>
        void AddPair(int shapeA, int shapeB);
    }
}
