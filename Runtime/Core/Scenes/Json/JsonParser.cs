using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// A strict JSON (RFC 8259) parser that records the path, line and column of every value.
    /// Core cannot use System.Text.Json (it targets netstandard2.1 for Unity), and scene errors
    /// must say where they are. Malformed text throws a <see cref="SceneException"/> whose one
    /// error names the path of the enclosing value and the line and column of the fault.
    /// Duplicate member names are an error too (a scene with two "mass" fields is a mistake).
    /// </summary>
    public sealed class JsonParser
    {
        /// <summary>Deepest nesting of arrays and objects: deep enough for any scene, shallow enough that hostile input cannot overflow the stack.</summary>
        public const int MaxDepth = 128;

        /// <summary>Most members in one object (the scene format has a few dozen fields; materials are the largest map).</summary>
        public const int MaxMembers = 10000;

        /// <summary>Longest member name, characters.</summary>
        public const int MaxNameLength = 256;

        /// <summary>Longest string value (names, file paths), characters.</summary>
        public const int MaxStringLength = 4096;

        /// <summary>Longest number, characters (a float needs at most about 15).</summary>
        public const int MaxNumberLength = 64;

        readonly string _text;
        int _pos;
        int _line = 1;
        int _lineStart;

        JsonParser(string text) => _text = text;

        /// <summary>Parses a whole document (one value, then only whitespace).</summary>
        public static JsonValue Parse(string text)
        {
            var p = new JsonParser(text);
            p.SkipWhitespace();
            JsonValue root = p.ParseValue(JsonPath.Root, 0);
            p.SkipWhitespace();
            if (p._pos < text.Length) p.Fail(JsonPath.Root, $"unexpected {p.Describe()} after the end of the document");
            return root;
        }

        int Column => _pos - _lineStart + 1;

        JsonValue ParseValue(string path, int depth)
        {
            if (depth > MaxDepth) Fail(path, $"nesting deeper than {MaxDepth} levels");
            if (_pos >= _text.Length) Fail(path, "unexpected end of text, expected a value");
            int line = _line, column = Column;
            char c = _text[_pos];
            switch (c)
            {
                case '{': return ParseObject(path, depth, line, column);
                case '[': return ParseArray(path, depth, line, column);
                case '"': return JsonValue.Parsed(JsonKind.String, ParseString(path, MaxStringLength, "string"), false, null, null, path, line, column);
                case 't': Expect("true", path); return JsonValue.Parsed(JsonKind.Bool, null, true, null, null, path, line, column);
                case 'f': Expect("false", path); return JsonValue.Parsed(JsonKind.Bool, null, false, null, null, path, line, column);
                case 'n': Expect("null", path); return JsonValue.Parsed(JsonKind.Null, null, false, null, null, path, line, column);
                default:
                    if (c == '-' || (c >= '0' && c <= '9'))
                        return JsonValue.Parsed(JsonKind.Number, ParseNumber(path), false, null, null, path, line, column);
                    Fail(path, $"unexpected {Describe()}, expected a value");
                    return null!;
            }
        }

        JsonValue ParseObject(string path, int depth, int line, int column)
        {
            var members = new List<KeyValuePair<string, JsonValue>>();
            var names = new HashSet<string>(System.StringComparer.Ordinal); // linear duplicate check
            for (bool more = Open('}'); more; more = Next(path, '}'))
            {
                SkipWhitespace();
                if (Peek() != '"') Fail(path, $"unexpected {Describe()}, expected a member name in double quotes");
                int keyLine = _line, keyColumn = Column;
                string key = ParseString(path, MaxNameLength, "member name");
                string memberPath = JsonPath.Member(path, key);
                if (!names.Add(key)) FailAt(memberPath, $"duplicate member '{key}'", keyLine, keyColumn);
                if (members.Count == MaxMembers) FailAt(memberPath, $"more than {MaxMembers} members in one object", keyLine, keyColumn);
                SkipWhitespace();
                if (Peek() != ':') Fail(memberPath, $"unexpected {Describe()}, expected ':'");
                _pos++;
                SkipWhitespace();
                members.Add(new KeyValuePair<string, JsonValue>(key, ParseValue(memberPath, depth + 1)));
            }
            return JsonValue.Parsed(JsonKind.Object, null, false, null, members, path, line, column);
        }

        JsonValue ParseArray(string path, int depth, int line, int column)
        {
            var items = new List<JsonValue>();
            for (bool more = Open(']'); more; more = Next(path, ']'))
            {
                SkipWhitespace();
                items.Add(ParseValue(JsonPath.Index(path, items.Count), depth + 1));
            }
            return JsonValue.Parsed(JsonKind.Array, null, false, items, null, path, line, column);
        }

        // Steps past an object's or array's opening bracket: false, past the closing one too,
        // when it is empty; true when a member or item follows.
        bool Open(char close)
        {
            _pos++;
            SkipWhitespace();
            if (Peek() != close) return true;
            _pos++;
            return false;
        }

        // After a member or item: true past a ',' (another follows), false past the closing
        // bracket; anything else is an error at the container's path.
        bool Next(string path, char close)
        {
            SkipWhitespace();
            char c = Peek();
            if (c == ',' || c == close)
            {
                _pos++;
                return c == ',';
            }
            Fail(path, $"unexpected {Describe()}, expected ',' or '{close}'");
            return false;
        }

        string ParseString(string path, int maxLength, string what)
        {
            _pos++; // opening quote
            var sb = new StringBuilder();
            while (true)
            {
                if (_pos >= _text.Length) Fail(path, "unterminated string");
                if (sb.Length > maxLength) Fail(path, $"{what} longer than {maxLength} characters");
                char c = _text[_pos];
                if (c == '"') { _pos++; return sb.ToString(); }
                if (c < 0x20) Fail(path, c == '\n' ? "unterminated string (a line break inside quotes)" : "control character inside a string");
                if (c != '\\') { sb.Append(c); _pos++; continue; }
                _pos++;
                if (_pos >= _text.Length) Fail(path, "unterminated string");
                char e = _text[_pos];
                switch (e)
                {
                    case '"': sb.Append('"'); break;
                    case '\\': sb.Append('\\'); break;
                    case '/': sb.Append('/'); break;
                    case 'b': sb.Append('\b'); break;
                    case 'f': sb.Append('\f'); break;
                    case 'n': sb.Append('\n'); break;
                    case 'r': sb.Append('\r'); break;
                    case 't': sb.Append('\t'); break;
                    case 'u':
                        if (_pos + 4 >= _text.Length || !int.TryParse(_text.Substring(_pos + 1, 4), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out int code))
                            Fail(path, "bad \\u escape: expected four hex digits");
                        else
                        {
                            sb.Append((char)code);
                            _pos += 4;
                        }
                        break;
                    default:
                        Fail(path, $"bad escape '\\{e}'");
                        break;
                }
                _pos++;
            }
        }

        // JSON's number grammar exactly: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
        string ParseNumber(string path)
        {
            int start = _pos;
            if (Peek() == '-') _pos++;
            if (Peek() == '0') _pos++;
            else if (IsDigit(Peek())) while (IsDigit(Peek())) _pos++;
            else Fail(path, $"unexpected {Describe()} in a number");
            if (Peek() == '.')
            {
                _pos++;
                if (!IsDigit(Peek())) Fail(path, "expected a digit after the decimal point");
                while (IsDigit(Peek())) _pos++;
            }
            if (Peek() == 'e' || Peek() == 'E')
            {
                _pos++;
                if (Peek() == '+' || Peek() == '-') _pos++;
                if (!IsDigit(Peek())) Fail(path, "expected a digit in the exponent");
                while (IsDigit(Peek())) _pos++;
            }
            if (IsDigit(Peek()) || char.IsLetter(Peek()) || Peek() == '.')
                Fail(path, $"unexpected {Describe()} in a number");
            if (_pos - start > MaxNumberLength)
                FailAt(path, $"number longer than {MaxNumberLength} characters ({SceneError.Clip(_text.Substring(start, SceneError.MaxEcho + 1))})", _line, start - _lineStart + 1);
            return _text.Substring(start, _pos - start);
        }

        static bool IsDigit(char c) => c >= '0' && c <= '9';

        char Peek() => _pos < _text.Length ? _text[_pos] : '\0';

        void Expect(string word, string path)
        {
            if (_pos + word.Length > _text.Length || string.CompareOrdinal(_text, _pos, word, 0, word.Length) != 0)
                Fail(path, $"unexpected {Describe()}, expected a value");
            _pos += word.Length;
            if (char.IsLetterOrDigit(Peek())) Fail(path, $"unexpected {Describe()} after '{word}'");
        }

        void SkipWhitespace()
        {
            while (_pos < _text.Length)
            {
                char c = _text[_pos];
                if (c == '\n') { _pos++; _line++; _lineStart = _pos; }
                else if (c == ' ' || c == '\t' || c == '\r') _pos++;
                else if (c == '\uFEFF' && _pos == 0) _pos++; // a byte-order mark some editors write
                else break;
            }
        }

        string Describe()
        {
            if (_pos >= _text.Length) return "end of text";
            char c = _text[_pos];
            if (c == '\n' || c == '\r') return "line break";
            if (c < 0x20) return $"control character U+{(int)c:X4}";
            if (char.IsLetter(c))
            {
                int end = _pos;
                while (end < _text.Length && end - _pos < 20 && char.IsLetterOrDigit(_text[end])) end++;
                return $"'{_text.Substring(_pos, end - _pos)}'";
            }
            return $"'{c}'";
        }

        void Fail(string path, string message) => FailAt(path, message, _line, Column);

        static void FailAt(string path, string message, int line, int column) =>
            throw new SceneException(new SceneError(path, message, line, column));
    }
}
