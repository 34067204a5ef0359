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
            // One readable line whatever the input: a 50 MB value is never echoed whole.
            Path = Clip(path, MaxPathLength);
            Message = Clip(message, MaxMessageLength);
            Line = line;
            Column = column;
        }

        /// <summary>Longest echo of a value from the file in a message: longer text keeps its start and "...".</summary>
        public const int MaxEcho = 40;

        /// <summary>Longest path kept in an error (longer paths keep their start and "...").</summary>
        public const int MaxPathLength = 300;

        /// <summary>Longest message kept in an error.</summary>
        public const int MaxMessageLength = 500;

        /// <summary>
        /// <paramref name="text"/> cut to <paramref name="max"/> characters (default
        /// <see cref="MaxEcho"/>) plus "..." when longer, with line breaks shown as spaces so an
        /// error stays on one line.
        /// </summary>
        public static string Clip(string text, int max = MaxEcho)
        {
            if (text == null) return "";
            string s = text.Length > max ? text.Substring(0, max) + "..." : text;
            return s.IndexOf('\n') >= 0 || s.IndexOf('\r') >= 0 ? s.Replace('\r', ' ').Replace('\n', ' ') : s;
        }

        /// <summary>
        /// The message of <paramref name="error"/> for a scene error: an
        /// <see cref="System.ArgumentException"/>'s " (Parameter 'x')" suffix is dropped (the JSON path
        /// names the field already).
        /// </summary>
        public static string MessageOf(System.Exception error)
        {
            string m = error.Message;
            if (error is System.ArgumentException a && a.ParamName != null)
            {
                string suffix = $" (Parameter '{a.ParamName}')";
                if (m.EndsWith(suffix, System.StringComparison.Ordinal)) m = m.Substring(0, m.Length - suffix.Length);
            }
            return m;
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
