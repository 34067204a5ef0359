namespace Fulcrum.Scenes
{
    /// <summary>Which ends of a <see cref="SceneChain"/> are jointed to the world (JSON <c>"none"</c>, <c>"first"</c>, <c>"both"</c>).</summary>
    public enum SceneChainAnchor : byte
    {
        /// <summary>A free chain.</summary>
        None = 0,
        /// <summary>The start of the first link is held by a ball joint to the world (a pendulum chain).</summary>
        First = 1,
        /// <summary>Both ends are held (a bridge).</summary>
        Both = 2,
    }
}
