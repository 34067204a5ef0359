namespace Fulcrum.Collision
{
    /// <summary>
    /// Receives the leaves whose bounds overlap a query box. A struct implementing this is
    /// passed by reference as a generic argument, so the call is direct and allocates nothing.
    /// </summary>
    internal interface ITreeOverlapCallback
    {
        /// <summary>Called per overlapping leaf; return false to stop the query.</summary>
        bool Visit(int proxyId, int userData);
    }
}
