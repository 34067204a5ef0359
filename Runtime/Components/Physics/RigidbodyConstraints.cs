using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// Degrees of freedom a <see cref="Rigidbody"/> may not use, with Unity's values. Axes are
    /// world axes. See <see cref="Rigidbody.constraints"/> for how Fulcrum enforces them.
    /// </summary>
    [Flags]
    public enum RigidbodyConstraints
    {
        /// <summary>Free motion.</summary>
        None = 0,
        /// <summary>No motion along world x.</summary>
        FreezePositionX = 2,
        /// <summary>No motion along world y.</summary>
        FreezePositionY = 4,
        /// <summary>No motion along world z.</summary>
        FreezePositionZ = 8,
        /// <summary>No rotation about world x.</summary>
        FreezeRotationX = 16,
        /// <summary>No rotation about world y.</summary>
        FreezeRotationY = 32,
        /// <summary>No rotation about world z.</summary>
        FreezeRotationZ = 64,
        /// <summary>No translation at all.</summary>
        FreezePosition = FreezePositionX | FreezePositionY | FreezePositionZ,
        /// <summary>No rotation at all.</summary>
        FreezeRotation = FreezeRotationX | FreezeRotationY | FreezeRotationZ,
        /// <summary>Neither translation nor rotation.</summary>
        FreezeAll = FreezePosition | FreezeRotation,
    }
}
