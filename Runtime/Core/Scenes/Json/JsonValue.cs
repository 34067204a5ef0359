using System;
using System.Collections.Generic;
using System.Globalization;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// One parsed JSON value with where it came from: its <see cref="Path"/> in the document
    /// and the <see cref="Line"/>/<see cref="Column"/> where it starts (1-based; 0 for values
    /// built in code). Numbers keep their source text, so a float field parses straight from
    /// the text (no double rounding on the way) and an integer field can insist on an integer.
    /// Object members keep their order.
    /// </summary>
    public sealed class JsonValue
    {
        static readonly IReadOnlyList<JsonValue> NoItems = System.Array.Empty<JsonValue>();
        static readonly IReadOnlyList<KeyValuePair<string, JsonValue>> NoMembers = System.Array.Empty<KeyValuePair<string, JsonValue>>();

        readonly string? _text;
        readonly bool _bool;
        readonly List<JsonValue>? _items;
        readonly List<KeyValuePair<string, JsonValue>>? _members;

        JsonValue(JsonKind kind, string? text, bool flag, List<JsonValue>? items, List<KeyValuePair<string, JsonValue>>? members,
            string path, int line, int column)
        {
            Kind = kind;
            _text = text;
            _bool = flag;
            _items = items;
            _members = members;
            Path = path;
            Line = line;
            Column = column;
        }

        /// <summary>What kind of value this is.</summary>
        public JsonKind Kind { get; }

        /// <summary>The location in the document, e.g. <c>$.bodies[3].shape</c>; empty for values built in code.</summary>
        public string Path { get; }

        /// <summary>The source line where the value starts, 1-based; 0 when built in code.</summary>
        public int Line { get; }

        /// <summary>The source column (in UTF-16 code units) where the value starts, 1-based; 0 when built in code.</summary>
        public int Column { get; }

        /// <summary>The value of a <see cref="JsonKind.Bool"/>.</summary>
        public bool AsBool => Kind == JsonKind.Bool ? _bool : throw WrongKind(JsonKind.Bool);

        /// <summary>The value of a <see cref="JsonKind.String"/>.</summary>
        public string AsString => Kind == JsonKind.String ? _text! : throw WrongKind(JsonKind.String);

        /// <summary>The source text of a <see cref="JsonKind.Number"/> (e.g. <c>-9.81</c>, <c>1e5</c>).</summary>
        public string NumberText => Kind == JsonKind.Number ? _text! : throw WrongKind(JsonKind.Number);

        /// <summary>The items of an array (empty for other kinds).</summary>
        public IReadOnlyList<JsonValue> Items => (IReadOnlyList<JsonValue>?)_items ?? NoItems;

        /// <summary>The members of an object in source order (empty for other kinds).</summary>
        public IReadOnlyList<KeyValuePair<string, JsonValue>> Members => (IReadOnlyList<KeyValuePair<string, JsonValue>>?)_members ?? NoMembers;

        /// <summary>The member called <paramref name="name"/> of an object, or null.</summary>
        public JsonValue? this[string name]
        {
            get
            {
                if (_members == null) return null;
                foreach (KeyValuePair<string, JsonValue> m in _members)
                    if (m.Key == name) return m.Value;
                return null;
            }
        }

        /// <summary>A lower-case name for the kind, for error messages ("number", "array", ...).</summary>
        public string KindName => NameOf(Kind);

        /// <summary>A lower-case name for a kind, for error messages.</summary>
        public static string NameOf(JsonKind kind) => kind switch
        {
            JsonKind.Null => "null",
            JsonKind.Bool => "boolean",
            JsonKind.Number => "number",
            JsonKind.String => "string",
            JsonKind.Array => "array",
            _ => "object",
        };

        InvalidOperationException WrongKind(JsonKind wanted) =>
            new InvalidOperationException($"{Path}: expected a {NameOf(wanted)}, got {KindName}.");

        /// <summary>The <c>null</c> value.</summary>
        public static JsonValue Null() => new JsonValue(JsonKind.Null, null, false, null, null, "", 0, 0);

        /// <summary>A boolean value.</summary>
        public static JsonValue From(bool value) => new JsonValue(JsonKind.Bool, null, value, null, null, "", 0, 0);

        /// <summary>A string value.</summary>
        public static JsonValue From(string value) => new JsonValue(JsonKind.String, value, false, null, null, "", 0, 0);

        /// <summary>
        /// A float written with round-trip formatting ("R", invariant culture), so that parsing
        /// the text gives back exactly <paramref name="value"/>. Must be finite (JSON has no NaN).
        /// </summary>
        public static JsonValue From(float value)
        {
            if (!float.IsFinite(value)) throw new ArgumentException($"JSON cannot hold {value}.", nameof(value));
            return new JsonValue(JsonKind.Number, value.ToString("R", CultureInfo.InvariantCulture), false, null, null, "", 0, 0);
        }

        /// <summary>An integer value.</summary>
        public static JsonValue From(int value) =>
            new JsonValue(JsonKind.Number, value.ToString(CultureInfo.InvariantCulture), false, null, null, "", 0, 0);

        /// <summary>An array holding <paramref name="items"/> (the list is kept, not copied).</summary>
        public static JsonValue Array(List<JsonValue> items) => new JsonValue(JsonKind.Array, null, false, items, null, "", 0, 0);

        /// <summary>An object holding <paramref name="members"/> in order (the list is kept, not copied).</summary>
        public static JsonValue Object(List<KeyValuePair<string, JsonValue>> members) =>
            new JsonValue(JsonKind.Object, null, false, null, members, "", 0, 0);

        internal static JsonValue Parsed(JsonKind kind, string? text, bool flag, List<JsonValue>? items,
            List<KeyValuePair<string, JsonValue>>? members, string path, int line, int column) =>
            new JsonValue(kind, text, flag, items, members, path, line, column);
    }
}
