using System;

namespace Fulcrum.Components
{
    /// <summary>A sphere collider, like Unity's.</summary>
    public sealed class SphereCollider : Collider
    {
        float _radius = 0.5f;

        /// <summary>Radius, metres, &gt; 0. Default: 0.5.</summary>
        public float radius
        {
            get => _radius;
            set
            {
                FieldCheck.Size(value, this, nameof(radius));
                ThrowIfStepping(nameof(radius));
                _radius = value;
                Rebuild();
            }
        }

        internal override ShapeGeometry BuildGeometry() => ShapeGeometry.Sphere(_radius);
    }
}
