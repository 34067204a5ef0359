using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// <c>{"type": "plane", "normal": [nx, ny, nz], "offset": d}</c>: the half-space
    /// n . x &lt;= d in the body frame (normalised when built). Static bodies only.
    /// </summary>
    public sealed class ScenePlane : SceneShape
    {
        /// <inheritdoc/>
        public override SceneShapeType Type => SceneShapeType.Plane;

        /// <summary><c>normal</c>: outward normal, non-zero. Default: (0, 1, 0).</summary>
        public Vector3 Normal { get; set; } = Vector3.UnitY;

        /// <summary><c>offset</c>: distance of the surface from the origin along the normal, m. Default: 0.</summary>
        public float Offset { get; set; }
    }
}
