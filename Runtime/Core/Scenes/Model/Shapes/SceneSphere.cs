namespace Fulcrum.Scenes
{
    /// <summary><c>{"type": "sphere", "radius": r}</c>.</summary>
    public sealed class SceneSphere : SceneShape
    {
        /// <inheritdoc/>
        public override SceneShapeType Type => SceneShapeType.Sphere;

        /// <summary><c>radius</c>, m, &gt; 0. Required.</summary>
        public float Radius { get; set; }
    }
}
