using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>A box collider, like Unity's: <see cref="size"/> is the full size (Core takes half-extents).</summary>
    public sealed class BoxCollider : Collider
    {
        Vector3 _size = Vector3.One;

        /// <summary>Full size on each local axis, metres, each &gt; 0. Default: (1, 1, 1).</summary>
        public Vector3 size
        {
            get => _size;
            set
            {
                if (!(Validate.IsFinite(value) && value.X > 0 && value.Y > 0 && value.Z > 0))
                    throw new ArgumentException($"{this}: size must be finite and > 0 on every axis, got {value}.", nameof(size));
                SetShapeField(ref _size, value, nameof(size));
            }
        }

        internal override ShapeGeometry BuildGeometry() => ShapeGeometry.Box(0.5f * _size);
    }
}
