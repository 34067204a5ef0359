using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>Where a swept shape first touched another.</summary>
    public struct ShapeCastHit : IQueryHit
    {
        /// <summary>The shape hit.</summary>
        public ShapeHandle Shape;
        /// <summary>Its body.</summary>
        public BodyHandle Body;
        /// <summary>The touching point on the hit shape's surface, world, metres.</summary>
        public Vector3 Point;
        /// <summary>The hit shape's surface normal there (unit, facing the cast shape).</summary>
        public Vector3 Normal;
        /// <summary>How far the cast shape travelled before touching, metres.</summary>
        public float Distance;

        float IQueryHit.Distance => Distance;
        ShapeHandle IQueryHit.Shape => Shape;
    }
}
