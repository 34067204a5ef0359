using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary><c>{"type": "box", "halfExtents": [hx, hy, hz]}</c>.</summary>
    public sealed class SceneBox : SceneShape
    {
        /// <inheritdoc/>
        public override SceneShapeType Type => SceneShapeType.Box;

        /// <summary><c>halfExtents</c>, m, each &gt; 0. Required.</summary>
        public Vector3 HalfExtents { get; set; }
    }
}
