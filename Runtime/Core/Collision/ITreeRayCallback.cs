
namespace Fulcrum.Collision
{
    /// <summary>
    /// Receives the leaves whose bounds a ray segment crosses (in no particular order). Passed
    /// by reference as a generic struct argument, like <see cref="ITreeOverlapCallback"/>.
    /// </summary>
    internal interface ITreeRayCallback
    {
        /// <summary>
        /// Called per leaf whose box the segment origin + t direction, t in [0, maxFraction],
        /// crosses. Returns the new maximum fraction: the same to go on, a smaller one to clip
        /// the ray (closest-hit searches), 0 to stop.
        /// </summary>
        float Visit(int proxyId, int userData, float maxFraction);
    }
}
