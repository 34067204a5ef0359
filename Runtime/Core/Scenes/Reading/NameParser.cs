namespace Fulcrum.Scenes
{
    /// <summary>
    /// Reads a scene-format spelling into a value (the shape of <see cref="SceneNames"/>'
    /// TryParse overloads), so <see cref="JsonObjectReader.Name{T}"/> reads and reports every
    /// named member the same way.
    /// </summary>
    internal delegate bool NameParser<T>(string name, out T value);
}
