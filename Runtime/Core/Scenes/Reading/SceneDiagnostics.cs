using System.Collections.Generic;

namespace Fulcrum.Scenes
{
    /// <summary>Collects scene errors in the order they are found, with source locations where known.</summary>
    internal sealed class SceneDiagnostics
    {
        public readonly List<SceneError> Errors = new List<SceneError>();

        /// <summary>Paths of values that were rejected and left at their defaults.</summary>
        public readonly List<string> Rejected = new List<string>();

        public bool HasErrors => Errors.Count > 0;

        /// <summary>An error at <paramref name="path"/>, located at <paramref name="at"/>'s start when given.</summary>
        public void Add(string path, string message, JsonValue? at = null)
        {
            Errors.Add(new SceneError(path, message, at?.Line ?? 0, at?.Column ?? 0));
            Rejected.Add(path);
        }

        /// <summary>An unknown member: an error, but nothing was left at a default because of it.</summary>
        public void AddUnknown(string path, string message, JsonValue at) =>
            Errors.Add(new SceneError(path, message, at.Line, at.Column));
    }
}
