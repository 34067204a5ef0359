using System.Collections.Generic;
using System.IO;
using System.Text;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Reads and writes scene files (format <c>fulcrum-scene/1</c>, DESIGN.md). Reading reports
    /// every problem at once, each with its JSON path and source line and column; writing is
    /// exact: <c>Parse(Save(doc))</c> equals <c>doc</c> field for field, and saving that again
    /// gives the same text.
    /// </summary>
    public static class SceneFile
    {
        /// <summary>Reads and validates a scene; throws a <see cref="SceneException"/> listing every problem.</summary>
        public static SceneDocument Parse(string text)
        {
            IReadOnlyList<SceneError> errors = Check(text, out SceneDocument? doc);
            if (errors.Count > 0) throw new SceneException(errors);
            return doc!;
        }

        /// <summary>Reads and validates the scene file at <paramref name="path"/> (UTF-8).</summary>
        public static SceneDocument Load(string path) => Parse(File.ReadAllText(path, Encoding.UTF8));

        /// <summary>
        /// Reads and validates a scene, returning every problem found (empty when valid).
        /// <paramref name="document"/> is the document read, or null when the text is not JSON.
        /// </summary>
        public static IReadOnlyList<SceneError> Check(string text, out SceneDocument? document)
        {
            document = null;
            JsonValue root;
            try
            {
                root = JsonParser.Parse(text);
            }
            catch (SceneException e)
            {
                return e.Errors;
            }
            var d = new SceneDiagnostics();
            document = SceneReader.Read(root, d);
            var errors = new List<SceneError>(d.Errors);
            Dictionary<string, JsonValue> located = Locate(root);
            foreach (SceneError e in SceneValidator.Validate(document))
            {
                // A value the reader already rejected was left at its default: the validator's
                // complaint about that default (or about its parent) would only repeat it.
                if (Overlaps(e.Path, d.Rejected)) continue;
                JsonValue? at = Nearest(e.Path, located);
                errors.Add(at != null ? e.At(at.Line, at.Column) : e);
            }
            return errors;
        }

        /// <summary>The scene as JSON text (see <see cref="SceneWriter"/> for the layout).</summary>
        public static string Save(SceneDocument document) => JsonFormatter.Format(SceneWriter.Write(document));

        /// <summary>Writes the scene to <paramref name="path"/> (UTF-8, no byte-order mark).</summary>
        public static void Save(SceneDocument document, string path) =>
            File.WriteAllText(path, Save(document), new UTF8Encoding(false));

        static Dictionary<string, JsonValue> Locate(JsonValue root)
        {
            var map = new Dictionary<string, JsonValue>();
            var stack = new Stack<JsonValue>();
            stack.Push(root);
            while (stack.Count > 0)
            {
                JsonValue v = stack.Pop();
                map[v.Path] = v;
                foreach (JsonValue item in v.Items) stack.Push(item);
                foreach (KeyValuePair<string, JsonValue> m in v.Members) stack.Push(m.Value);
            }
            return map;
        }

        // The value at the path, or at its nearest ancestor in the text (a defaulted field was never written).
        static JsonValue? Nearest(string path, Dictionary<string, JsonValue> located)
        {
            while (true)
            {
                if (located.TryGetValue(path, out JsonValue? v)) return v;
                int cut = path.LastIndexOfAny(new[] { '.', '[' });
                if (cut <= 0) return null;
                path = path.Substring(0, cut);
            }
        }

        static bool Overlaps(string path, List<string> rejected)
        {
            foreach (string r in rejected)
                if (IsWithin(path, r) || IsWithin(r, path)) return true;
            return false;
        }

        // True when inner is outer or lies below it.
        static bool IsWithin(string inner, string outer) =>
            inner.StartsWith(outer, System.StringComparison.Ordinal)
            && (inner.Length == outer.Length || inner[outer.Length] == '.' || inner[outer.Length] == '[');
    }
}
