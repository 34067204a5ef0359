using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// Everything needed to attach a shape to a body. Start from <see cref="Default"/> and set
    /// the fields you need.
    /// </summary>
    public struct ShapeDef
    {
        /// <summary>The geometry. Required.</summary>
        public ShapeGeometry Geometry;
        /// <summary>Pose of the shape in the body frame. Default: identity.</summary>
        public Pose LocalPose;
        /// <summary>Density in kg/m^3, used for the body's mass unless the mass is set directly. Default: 1000 (water).</summary>
        public float Density;
        /// <summary>Coulomb friction coefficient, &gt;= 0. Default: 0.6.</summary>
        public float Friction;
        /// <summary>Coefficient of restitution in [0, 1]. Default: 0.</summary>
        public float Restitution;
        /// <summary>How friction combines with the other shape's. Default: Average.</summary>
        public CombineMode FrictionCombine;
        /// <summary>How restitution combines with the other shape's. Default: Average.</summary>
        public CombineMode RestitutionCombine;
        /// <summary>A sensor (trigger) reports overlaps but has no physical response. Default: false.</summary>
        public bool IsSensor;
        /// <summary>The collision layer, 0..31. Default: 0.</summary>
        public int Layer;
        /// <summary>Bit mask of the layers this shape collides with. Default: all.</summary>
        public uint CollidesWith;
        /// <summary>Free for the user: a number carried back in events and queries. Default: 0.</summary>
        public ulong UserData;

        /// <summary>The defaults documented on each field, with the given geometry.</summary>
        public static ShapeDef Of(ShapeGeometry geometry)
        {
            ShapeDef d = Default;
            d.Geometry = geometry;
            return d;
        }

        /// <summary>The defaults documented on each field (geometry unset).</summary>
        public static ShapeDef Default => new ShapeDef
        {
            LocalPose = Pose.Identity,
            Density = 1000f,
            Friction = 0.6f,
            Restitution = 0f,
            FrictionCombine = CombineMode.Average,
            RestitutionCombine = CombineMode.Average,
            Layer = 0,
            CollidesWith = uint.MaxValue,
        };

        internal readonly void Validate()
        {
            if (Geometry.Type == ShapeType.Sphere && Geometry.Radius == 0 && Geometry.Data == null)
                throw new System.ArgumentException("shape.Geometry is unset: build it with ShapeGeometry.Sphere/Box/Capsule/Plane/...", "Geometry");
            Mathematics.Validate.Finite(LocalPose.Position, "shape.LocalPose.Position");
            Limits.CheckPosition(LocalPose.Position, "shape.LocalPose.Position");
            if (Geometry.Type == ShapeType.Plane)
            {
                if (System.Math.Abs(Geometry.Offset) > Limits.MaxPosition)
                    throw new System.ArgumentException($"plane.offset must be within +-{Limits.MaxPosition:G} m (Limits.MaxPosition), got {Geometry.Offset}.", "Geometry");
            }
            else
            {
                // Every size a pair function or a mass formula squares or cubes: its bounds.
                Aabb box = Geometry.ComputeAabb(Pose.Identity);
                Vector3 far = Vector3.Max(Vector3.Abs(box.Min), Vector3.Abs(box.Max));
                float size = System.Math.Max(far.X, System.Math.Max(far.Y, far.Z));
                float thinnest = Geometry.Type == ShapeType.Sphere || Geometry.Type == ShapeType.Capsule ? Geometry.Radius
                    : Geometry.Type == ShapeType.Box ? System.Math.Min(Geometry.HalfExtents.X, System.Math.Min(Geometry.HalfExtents.Y, Geometry.HalfExtents.Z))
                    : Limits.MinShapeSize;
                if (!(thinnest >= Limits.MinShapeSize))
                    throw new System.ArgumentException($"shape.Geometry ({Geometry.Type}) is {thinnest:G} m thin; at least {Limits.MinShapeSize:G} m (Limits.MinShapeSize).", "Geometry");
                if (!(size <= Limits.MaxShapeSize))
                    throw new System.ArgumentException($"shape.Geometry ({Geometry.Type}) reaches {size:G} m from its origin; at most {Limits.MaxShapeSize:G} m (Limits.MaxShapeSize).", "Geometry");
            }
            Mathematics.Validate.Rotation(LocalPose.Rotation, "shape.LocalPose.Rotation");
            Mathematics.Validate.NonNegative(Density, "shape.Density");
            Mathematics.Validate.NonNegative(Friction, "shape.Friction");
            Mathematics.Validate.NonNegative(Restitution, "shape.Restitution");
            if (Restitution > 1f) throw new System.ArgumentException($"shape.Restitution must be in [0, 1], got {Restitution}.", "Restitution");
            if (Layer < 0 || Layer > 31) throw new System.ArgumentException($"shape.Layer must be in 0..31, got {Layer}.", "Layer");
        }
    }
}
