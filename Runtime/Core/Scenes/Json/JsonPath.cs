using System.Text;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Builds JSONPath-style locations such as <c>$.bodies[3].shape.radius</c>: the root is
    /// <c>$</c>, members are <c>.name</c> (or <c>["odd name"]</c> when the name is not an
    /// identifier), array items are <c>[i]</c>. Scene errors are reported at these paths.
    /// </summary>
    public static class JsonPath
    {
        /// <summary>The path of the document root.</summary>
        public const string Root = "$";

        /// <summary>The path of member <paramref name="name"/> of the object at <paramref name="parent"/>.</summary>
        public static string Member(string parent, string name) =>
            IsIdentifier(name) ? parent + "." + name : parent + "[" + Quote(name) + "]";

        /// <summary>The path of item <paramref name="index"/> of the array at <paramref name="parent"/>.</summary>
        public static string Index(string parent, int index) =>
            parent + "[" + index.ToString(System.Globalization.CultureInfo.InvariantCulture) + "]";

        static bool IsIdentifier(string name)
        {
            if (name.Length == 0 || char.IsDigit(name[0])) return false;
            foreach (char c in name)
                if (!(c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')))
                    return false;
            return true;
        }

        /// <summary>A JSON string literal for <paramref name="s"/> (quotes and escapes added).</summary>
        public static string Quote(string s)
        {
            var sb = new StringBuilder(s.Length + 2);
            sb.Append('"');
            foreach (char c in s)
            {
                switch (c)
                {
                    case '"': sb.Append("\\\""); break;
                    case '\\': sb.Append("\\\\"); break;
                    case '\n': sb.Append("\\n"); break;
                    case '\r': sb.Append("\\r"); break;
                    case '\t': sb.Append("\\t"); break;
                    case '\b': sb.Append("\\b"); break;
                    case '\f': sb.Append("\\f"); break;
                    default:
                        if (c < 0x20) sb.Append("\\u").Append(((int)c).ToString("x4", System.Globalization.CultureInfo.InvariantCulture));
                        else sb.Append(c);
                        break;
                }
            }
            sb.Append('"');
            return sb.ToString();
        }
    }
}
