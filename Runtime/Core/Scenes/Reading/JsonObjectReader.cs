using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using System.Text;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Reads the members of one JSON object into typed values, reporting each problem (wrong
    /// type, missing required member, non-finite number) at the member's path, and, on
    /// <see cref="Finish"/>, every member nobody asked for as an unknown field. A missing
    /// optional member, or one given as <c>null</c>, yields the fallback.
    /// </summary>
    internal sealed class JsonObjectReader
    {
        readonly JsonValue _obj;
        readonly SceneDiagnostics _d;
        readonly List<string> _known = new List<string>();

        JsonObjectReader(JsonValue obj, SceneDiagnostics d)
        {
            _obj = obj;
            _d = d;
        }

        public string Path => _obj.Path;

        public JsonValue Value => _obj;

        /// <summary>A reader for <paramref name="v"/>, or null (and an error) when it is not an object.</summary>
        public static JsonObjectReader? Open(JsonValue v, SceneDiagnostics d, string what = "an object")
        {
            if (v.Kind == JsonKind.Object) return new JsonObjectReader(v, d);
            d.Add(v.Path, $"expected {what}, got {v.KindName}", v);
            return null;
        }

        /// <summary>
        /// A reader for an object whose required <c>type</c> member picks its kind from
        /// <paramref name="types"/> (shapes, soft meshes, joints, generators), with the kind in
        /// <paramref name="kind"/>; null (and an error) when <paramref name="v"/> is not an object
        /// or its type is missing or unknown.
        /// </summary>
        public static JsonObjectReader? OpenTyped<T>(JsonValue v, SceneDiagnostics d, string what, (T Value, string Name)[] types, string typeWhat, out T kind)
            where T : struct, System.Enum
        {
            kind = default;
            JsonObjectReader? r = Open(v, d, what);
            return r != null && r.Name("type", types, typeWhat, out kind, required: true) ? r : null;
        }

        string PathOf(string key) => JsonPath.Member(_obj.Path, key);

        /// <summary>The member, or null when absent or <c>null</c>; reports it when required and missing.</summary>
        public JsonValue? Take(string key, bool required = false)
        {
            if (!_known.Contains(key)) _known.Add(key);
            JsonValue? v = _obj[key];
            if (v == null || v.Kind == JsonKind.Null)
            {
                if (required) _d.Add(PathOf(key), v == null ? "missing required field" : "must not be null", v ?? _obj);
                return null;
            }
            return v;
        }

        /// <summary>Marks a member as known without reading it (it was read elsewhere).</summary>
        public void Known(string key)
        {
            if (!_known.Contains(key)) _known.Add(key);
        }

        public float Float(string key, float fallback, bool required = false) => OptionalFloat(key, required) ?? fallback;

        /// <summary>The member's number; null when absent (reported when required) or not a float (reported).</summary>
        public float? OptionalFloat(string key, bool required = false)
        {
            JsonValue? v = Take(key, required);
            return v != null && ReadFloat(v, _d, out float f) ? f : (float?)null;
        }

        public int Int(string key, int fallback, bool required = false) => OptionalInt(key, required) ?? fallback;

        /// <summary>The member's integer; null when absent (reported when required) or not an int (reported).</summary>
        public int? OptionalInt(string key, bool required = false)
        {
            JsonValue? v = Take(key, required);
            return v != null && ReadInt(v, _d, out int i) ? i : (int?)null;
        }

        public bool? OptionalBool(string key)
        {
            JsonValue? v = Take(key);
            if (v == null) return null;
            if (v.Kind == JsonKind.Bool) return v.AsBool;
            _d.Add(v.Path, $"expected true or false, got {Describe(v)}", v);
            return null;
        }

        /// <summary>An array of integers of any length; null when absent or wrong.</summary>
        public int[]? IntList(string key)
        {
            JsonValue? v = Take(key);
            if (v == null) return null;
            if (v.Kind != JsonKind.Array)
            {
                _d.Add(v.Path, $"expected an array of integers, got {Describe(v)}", v);
                return null;
            }
            return ReadInts(v.Items);
        }

        public bool Bool(string key, bool fallback)
        {
            JsonValue? v = Take(key);
            if (v == null) return fallback;
            if (v.Kind == JsonKind.Bool) return v.AsBool;
            _d.Add(v.Path, $"expected true or false, got {v.KindName}", v);
            return fallback;
        }

        public string? String(string key, bool required = false)
        {
            JsonValue? v = Take(key, required);
            if (v == null) return null;
            if (v.Kind == JsonKind.String) return v.AsString;
            _d.Add(v.Path, $"expected a string, got {v.KindName}", v);
            return null;
        }

        /// <summary>
        /// A member that names one value of an enumeration, spelled as in <paramref name="names"/>
        /// (one of <see cref="SceneNames"/>' tables): true with the value; false when absent
        /// (reported when required), not a string, or an unknown name, which is reported with the
        /// table's spellings.
        /// </summary>
        public bool Name<T>(string key, (T Value, string Name)[] names, string what, out T value, bool required = false) where T : struct, System.Enum
        {
            value = default;
            string? name = String(key, required);
            if (name == null) return false;
            if (SceneNames.ValueOf(names, name, default, out value)) return true;
            Unknown(key, what, name, SceneNames.Spellings(names));
            return false;
        }

        /// <summary>
        /// A member that is one of the strings <paramref name="allowed"/>: that string; null when
        /// absent, not a string, or another string, which is reported as an unknown
        /// <paramref name="key"/> with the allowed spellings.
        /// </summary>
        public string? OneOf(string key, params string[] allowed)
        {
            string? s = String(key);
            if (s == null || System.Array.IndexOf(allowed, s) >= 0) return s;
            Unknown(key, key, s, SceneNames.Spellings(allowed));
            return null;
        }

        /// <summary>Reports the member's string <paramref name="name"/> as no known <paramref name="what"/>, listing the <paramref name="expected"/> spellings.</summary>
        public void Unknown(string key, string what, string name, string expected) =>
            _d.Add(PathOf(key), $"unknown {what} '{name}' (expected {expected})", _obj[key]);

        public Vector3 Vector(string key, Vector3 fallback, bool required = false)
        {
            JsonValue? v = Take(key, required);
            return v != null && ReadVector(v, _d, out Vector3 r) ? r : fallback;
        }

        public Quaternion Rotation(string key, Quaternion fallback)
        {
            JsonValue? v = Take(key);
            if (v == null) return fallback;
            if (!ReadFloats(v, _d, 4, "a quaternion [x, y, z, w]", out float[] f)) return fallback;
            return new Quaternion(f[0], f[1], f[2], f[3]);
        }

        public int[]? Ints(string key, int count, bool required = false)
        {
            JsonValue? v = Take(key, required);
            if (v == null) return null;
            if (v.Kind != JsonKind.Array || v.Items.Count != count)
            {
                _d.Add(v.Path, $"expected an array of {count} integers, got {Describe(v)}", v);
                return null;
            }
            return ReadInts(v.Items);
        }

        // Every item as an integer (each bad one reported); null when any is not.
        int[]? ReadInts(IReadOnlyList<JsonValue> items)
        {
            var r = new int[items.Count];
            bool ok = true;
            for (int i = 0; i < r.Length; i++) ok &= ReadInt(items[i], _d, out r[i]);
            return ok ? r : null;
        }

        /// <summary>An array of [x, y, z] items (points, vertices, probes); null when absent or wrong.</summary>
        public List<Vector3>? Vectors(string key, bool required = false)
        {
            JsonValue? v = Take(key, required);
            if (v == null) return null;
            if (v.Kind != JsonKind.Array)
            {
                _d.Add(v.Path, $"expected an array of [x, y, z] points, got {v.KindName}", v);
                return null;
            }
            var list = new List<Vector3>(v.Items.Count);
            foreach (JsonValue item in v.Items)
                if (ReadVector(item, _d, out Vector3 p)) list.Add(p);
            return list.Count == v.Items.Count ? list : null;
        }

        /// <summary>The items of an array member (empty when absent; an error when not an array).</summary>
        public IReadOnlyList<JsonValue> Array(string key, bool required = false)
        {
            JsonValue? v = Take(key, required);
            if (v == null) return System.Array.Empty<JsonValue>();
            if (v.Kind == JsonKind.Array) return v.Items;
            _d.Add(v.Path, $"expected an array, got {v.KindName}", v);
            return System.Array.Empty<JsonValue>();
        }

        /// <summary>Reports every member that no reader asked for.</summary>
        public void Finish()
        {
            foreach (KeyValuePair<string, JsonValue> m in _obj.Members)
            {
                if (_known.Contains(m.Key)) continue;
                var sb = new StringBuilder("unknown field");
                if (_known.Count > 0) sb.Append(" (expected one of: ").Append(string.Join(", ", _known)).Append(')');
                _d.AddUnknown(m.Value.Path, sb.ToString(), m.Value);
            }
        }

        public static bool ReadFloat(JsonValue v, SceneDiagnostics d, out float f)
        {
            f = 0;
            if (v.Kind != JsonKind.Number)
            {
                d.Add(v.Path, $"expected a number, got {Describe(v)}", v);
                return false;
            }
            // Parsing the text straight to float rounds once (text -> double -> float could round twice).
            if (!float.TryParse(v.NumberText, NumberStyles.Float, CultureInfo.InvariantCulture, out f) || !float.IsFinite(f))
            {
                d.Add(v.Path, $"{SceneError.Clip(v.NumberText)} is out of the range of a float", v);
                return false;
            }
            return true;
        }

        public static bool ReadInt(JsonValue v, SceneDiagnostics d, out int i)
        {
            i = 0;
            if (v.Kind != JsonKind.Number)
            {
                d.Add(v.Path, $"expected an integer, got {Describe(v)}", v);
                return false;
            }
            if (!int.TryParse(v.NumberText, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out i))
            {
                d.Add(v.Path, $"expected an integer, got {SceneError.Clip(v.NumberText)}", v);
                return false;
            }
            return true;
        }

        public static bool ReadVector(JsonValue v, SceneDiagnostics d, out Vector3 r)
        {
            r = default;
            if (!ReadFloats(v, d, 3, "an array of 3 numbers [x, y, z]", out float[] f)) return false;
            r = new Vector3(f[0], f[1], f[2]);
            return true;
        }

        public static bool ReadFloats(JsonValue v, SceneDiagnostics d, int count, string what, out float[] f)
        {
            f = new float[count];
            if (v.Kind != JsonKind.Array || v.Items.Count != count)
            {
                d.Add(v.Path, $"expected {what}, got {Describe(v)}", v);
                return false;
            }
            bool ok = true;
            for (int i = 0; i < count; i++) ok &= ReadFloat(v.Items[i], d, out f[i]);
            return ok;
        }

        /// <summary>"string", "array of 2", "number 3.5"... for error messages.</summary>
        public static string Describe(JsonValue v) => v.Kind switch
        {
            JsonKind.Array => $"an array of {v.Items.Count}",
            JsonKind.Number => SceneError.Clip(v.NumberText),
            JsonKind.String => JsonPath.Quote(SceneError.Clip(v.AsString)),
            JsonKind.Bool => v.AsBool ? "true" : "false",
            _ => v.KindName,
        };
    }
}
