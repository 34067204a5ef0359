using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A box in rest coordinates whose vertices are held: fixed in the world where they start
    /// (inverse mass 0) when <see cref="Body"/> is none, otherwise attached to that rigid body
    /// at the point where they start (the scene file's <c>pinned: [{min, max, "to"}]</c>).
    /// Attached vertices keep their mass, so the body carries the soft body's weight.
    /// </summary>
    public struct SoftPin
    {
        /// <summary>Lower corner, rest coordinates, metres.</summary>
        public Vector3 Min;
        /// <summary>Upper corner, rest coordinates, metres.</summary>
        public Vector3 Max;
        /// <summary>The body the vertices are attached to; <see cref="BodyHandle.None"/> pins them to the world.</summary>
        public BodyHandle Body;

        /// <summary>Pins the vertices inside [min, max] to the world.</summary>
        public static SoftPin ToWorld(Vector3 min, Vector3 max) => new SoftPin { Min = min, Max = max };

        /// <summary>Attaches the vertices inside [min, max] to <paramref name="body"/>.</summary>
        public static SoftPin ToBody(Vector3 min, Vector3 max, BodyHandle body) => new SoftPin { Min = min, Max = max, Body = body };
    }
}
