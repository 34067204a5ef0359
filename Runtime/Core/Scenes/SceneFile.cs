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

        /// <summary>Reads and validates the scene file at <paramref name="path"/> (UTF-8; see <see cref="ReadText"/> for what is refused).</summary>
        public static SceneDocument Load(string path) => Parse(ReadText(path));

        /// <summary>Largest scene or mesh file read, bytes (64 MiB: a 1M-triangle mesh is about 40 MB of text).</summary>
        public const long MaxFileBytes = 64L << 20;

        /// <summary>
        /// Reads a scene or mesh file as UTF-8 text, refusing up front, with an
        /// <see cref="IOException"/> whose one-line message names the file: a missing file, a
        /// directory, a file over <see cref="MaxFileBytes"/>, and anything that reports no size
        /// (devices such as /dev/zero, FIFOs, /proc files: they are not regular files and could
        /// read forever or block). The read itself stops at the cap too, in case the file grows.
        /// </summary>
        public static string ReadText(string path)
        {
            if (string.IsNullOrEmpty(path)) throw new IOException("no file path given");
            if (Directory.Exists(path)) throw new IOException($"'{SceneError.Clip(path, 200)}' is a directory, not a file");
            var info = new FileInfo(path);
            if (!info.Exists) throw new FileNotFoundException($"'{SceneError.Clip(path, 200)}': no such file", path);
            long length = info.Length;
            if (length == 0)
                throw new IOException($"'{SceneError.Clip(path, 200)}' is empty or not a regular file (a device, FIFO or /proc file): nothing to read");
            if (length > MaxFileBytes)
                throw new IOException($"'{SceneError.Clip(path, 200)}' is {length} bytes; at most {MaxFileBytes} (SceneFile.MaxFileBytes) are read");
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read);
            var bytes = new byte[length];
            int read = 0;
            while (read < bytes.Length)
            {
                int n = stream.Read(bytes, read, bytes.Length - read);
                if (n <= 0) break;
                read += n;
            }
            if (stream.ReadByte() >= 0) throw new IOException($"'{SceneError.Clip(path, 200)}' grew while it was read");
            // Decode like File.ReadAllText: a UTF-8 byte-order mark is dropped.
            int skip = read >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF ? 3 : 0;
            return new UTF8Encoding(false).GetString(bytes, skip, read - skip);
        }

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
