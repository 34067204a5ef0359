using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>Where a ray met a shape.</summary>
    public struct RayHit : IQueryHit
    {
        /// <summary>The shape hit.</summary>
        public ShapeHandle Shape;
        /// <summary>Its body.</summary>
        public BodyHandle Body;
        /// <summary>The hit point on the shape's surface, world, metres.</summary>
        public Vector3 Point;
        /// <summary>The surface normal at the hit point (unit, facing the ray).</summary>
        public Vector3 Normal;
        /// <summary>Distance from the ray origin to the hit point, metres.</summary>
        public float Distance;

        float IQueryHit.Distance => Distance;
        ShapeHandle IQueryHit.Shape => Shape;
    }
}
