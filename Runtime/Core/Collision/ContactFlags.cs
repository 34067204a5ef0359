using System;

namespace Fulcrum.Collision
{
    /// <summary>State bits of a <see cref="Contact"/>.</summary>
    [Flags]
    internal enum ContactFlags : byte
    {
        None = 0,
        /// <summary>One shape is a sensor: overlap only, no manifold for the solver.</summary>
        Sensor = 1,
        /// <summary>Touching (or overlapping, for sensors) as of the last published events.</summary>
        Touching = 2,
        /// <summary>The narrow phase ran on the pair this step.</summary>
        Updated = 4,
        /// <summary>Sensor overlap found by this step's narrow phase.</summary>
        Overlapping = 8,
        /// <summary>The manifolds' points are stored in the shapes' frames and may be reused (see World.ManifoldReuse).</summary>
        Reusable = 16,
        /// <summary>Manifold reuse tracks A's pose in B's frame (B is the larger shape), not B's in A's.</summary>
        ReuseFromB = 32,
    }
}
