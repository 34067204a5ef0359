namespace Fulcrum.Scenes
{
    /// <summary>
    /// A <c>shape</c> object of a scene. One subclass per <see cref="SceneShapeType"/>
    /// (<see cref="SceneSphere"/>, <see cref="SceneBox"/>, ...), each holding that kind's fields.
    /// </summary>
    public abstract class SceneShape
    {
        /// <summary>The kind, written as the <c>type</c> field.</summary>
        public abstract SceneShapeType Type { get; }
    }
}
