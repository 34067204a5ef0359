using System;
using System.Collections.Generic;
using System.Globalization;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Splits mesh text files into lines of whitespace-separated tokens, dropping comments
    /// (from <c>#</c> to the end of the line) and blank lines; keeps 1-based line numbers for errors.
    /// </summary>
    internal static class TextTokens
    {
        /// <summary>The non-empty lines of <paramref name="text"/> as (line number, tokens).</summary>
        public static List<(int Line, string[] Tokens)> Lines(string text)
        {
            var lines = new List<(int, string[])>();
            string[] raw = text.Split('\n');
            for (int i = 0; i < raw.Length; i++)
            {
                string line = raw[i];
                int hash = line.IndexOf('#');
                if (hash >= 0) line = line.Substring(0, hash);
                string[] tokens = line.Split(new[] { ' ', '\t', '\r' }, StringSplitOptions.RemoveEmptyEntries);
                if (tokens.Length > 0) lines.Add((i + 1, tokens));
            }
            return lines;
        }

        /// <summary>Parses a float (invariant culture) or throws an ArgumentException naming the file field and line.</summary>
        public static float Float(string token, string field, int line)
        {
            if (!float.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out float v))
                throw new ArgumentException($"{field} line {line}: '{token}' is not a number.", field);
            return v;
        }

        /// <summary>Parses an int or throws an ArgumentException naming the file field and line.</summary>
        public static int Int(string token, string field, int line)
        {
            if (!int.TryParse(token, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v))
                throw new ArgumentException($"{field} line {line}: '{token}' is not an integer.", field);
            return v;
        }
    }
}
