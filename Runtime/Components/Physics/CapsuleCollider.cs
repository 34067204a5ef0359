using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// A capsule collider, like Unity's: <see cref="height"/> is the full height including the
    /// two caps, along the local axis <see cref="direction"/> (0 = x, 1 = y, 2 = z). A height
    /// below twice the radius makes a sphere, as in Unity.
    /// </summary>
    public sealed class CapsuleCollider : Collider
    {
        float _radius = 0.5f;
        float _height = 2f;
        int _direction = 1;

        /// <summary>Radius, metres, &gt; 0. Default: 0.5.</summary>
        public float radius
        {
            get => _radius;
            set => SetSize(ref _radius, value, nameof(radius));
        }

        /// <summary>Full height including the caps, metres, &gt; 0. Default: 2.</summary>
        public float height
        {
            get => _height;
            set => SetSize(ref _height, value, nameof(height));
        }

        /// <summary>The local axis of the capsule: 0 = x, 1 = y, 2 = z. Default: 1.</summary>
        public int direction
        {
            get => _direction;
            set
            {
                if ((uint)value > 2) throw new ArgumentException($"{this}: direction must be 0 (x), 1 (y) or 2 (z), got {value}.", nameof(direction));
                SetShapeField(ref _direction, value, nameof(direction));
            }
        }

        internal override ShapeGeometry BuildGeometry() => ShapeGeometry.Capsule(_radius, MathF.Max(0f, 0.5f * _height - _radius));

        // Core's capsule lies along local y; turn it onto x or z.
        internal override Pose LocalShapePose => new Pose(center, _direction switch
        {
            0 => Rotation.AboutAxis(2, -0.5f * MathF.PI),
            2 => Rotation.AboutAxis(0, 0.5f * MathF.PI),
            _ => Quaternion.Identity,
        });
    }
}
