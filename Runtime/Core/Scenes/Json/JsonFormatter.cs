using System.Collections.Generic;
using System.Text;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// Writes a <see cref="JsonValue"/> as indented text in one fixed layout, so that the same
    /// value always gives the same text (scene files diff cleanly): objects one member per
    /// line, arrays of plain values on one line (<c>[0, -9.81, 0]</c>), arrays holding arrays
    /// or objects one item per line. Numbers are written as their stored text.
    /// </summary>
    public static class JsonFormatter
    {
        /// <summary>The text of <paramref name="value"/>, ending with a line break.</summary>
        public static string Format(JsonValue value)
        {
            var sb = new StringBuilder();
            Write(sb, value, 0);
            sb.Append('\n');
            return sb.ToString();
        }

        static void Write(StringBuilder sb, JsonValue v, int indent)
        {
            switch (v.Kind)
            {
                case JsonKind.Null: sb.Append("null"); break;
                case JsonKind.Bool: sb.Append(v.AsBool ? "true" : "false"); break;
                case JsonKind.Number: sb.Append(v.NumberText); break;
                case JsonKind.String: sb.Append(JsonPath.Quote(v.AsString)); break;
                case JsonKind.Array: WriteArray(sb, v.Items, indent); break;
                default: WriteObject(sb, v.Members, indent); break;
            }
        }

        static void WriteArray(StringBuilder sb, IReadOnlyList<JsonValue> items, int indent)
        {
            bool flat = true;
            foreach (JsonValue item in items)
                if (item.Kind == JsonKind.Array || item.Kind == JsonKind.Object) flat = false;
            if (flat)
            {
                sb.Append('[');
                for (int i = 0; i < items.Count; i++)
                {
                    if (i > 0) sb.Append(", ");
                    Write(sb, items[i], indent);
                }
                sb.Append(']');
                return;
            }
            sb.Append("[\n");
            for (int i = 0; i < items.Count; i++)
            {
                Indent(sb, indent + 1);
                Write(sb, items[i], indent + 1);
                sb.Append(i + 1 < items.Count ? ",\n" : "\n");
            }
            Indent(sb, indent);
            sb.Append(']');
        }

        static void WriteObject(StringBuilder sb, IReadOnlyList<KeyValuePair<string, JsonValue>> members, int indent)
        {
            if (members.Count == 0)
            {
                sb.Append("{}");
                return;
            }
            sb.Append("{\n");
            for (int i = 0; i < members.Count; i++)
            {
                Indent(sb, indent + 1);
                sb.Append(JsonPath.Quote(members[i].Key)).Append(": ");
                Write(sb, members[i].Value, indent + 1);
                sb.Append(i + 1 < members.Count ? ",\n" : "\n");
            }
            Indent(sb, indent);
            sb.Append('}');
        }

        static void Indent(StringBuilder sb, int level) => sb.Append(' ', 2 * level);
    }
}
