
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
            set => SetSize(ref _radius, value, nameof(radius));
        }

        internal override ShapeGeometry BuildGeometry() => ShapeGeometry.Sphere(_radius);
    }
}
