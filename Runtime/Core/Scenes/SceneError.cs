using System.Globalization;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// One problem in a scene: where it is (<see cref="Path"/>, and the source line and
    /// column when the scene came from text) and what is wrong.
    /// Printed as <c>$.bodies[3].shape.radius: must be &gt; 0, got -1 (line 12, column 40)</c>.
    /// </summary>
    public sealed class SceneError
    {
        /// <summary>Creates an error.</summary>
        public SceneError(string path, string message, int line = 0, int column = 0)
        {
            Path = path;
            Message = message;
            Line = line;
            Column = column;
        }

        /// <summary>The JSON path of the offending value, e.g. <c>$.bodies[3].shape.radius</c>.</summary>
        public string Path { get; }

        /// <summary>What is wrong, e.g. <c>must be &gt; 0, got -1</c>.</summary>
        public string Message { get; }

        /// <summary>The source line, 1-based; 0 when unknown.</summary>
        public int Line { get; }

        /// <summary>The source column, 1-based; 0 when unknown.</summary>
        public int Column { get; }

        /// <summary>The same error located at a line and column.</summary>
        public SceneError At(int line, int column) => new SceneError(Path, Message, line, column);

        /// <inheritdoc/>
        public override string ToString() => Line > 0
            ? string.Format(CultureInfo.InvariantCulture, "{0}: {1} (line {2}, column {3})", Path, Message, Line, Column)
            : Path + ": " + Message;
    }
}
