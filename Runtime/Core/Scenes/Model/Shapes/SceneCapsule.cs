namespace Fulcrum.Scenes
{
    /// <summary><c>{"type": "capsule", "radius": r, "halfHeight": h}</c>: a capsule along the local y axis.</summary>
    public sealed class SceneCapsule : SceneShape
    {
        /// <inheritdoc/>
        public override SceneShapeType Type => SceneShapeType.Capsule;

        /// <summary><c>radius</c>, m, &gt; 0. Required.</summary>
        public float Radius { get; set; }

        /// <summary><c>halfHeight</c>: half the length of the inner segment, m, &gt;= 0. Required.</summary>
        public float HalfHeight { get; set; }
    }
}
