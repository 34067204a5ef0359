using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace Fulcrum.Runner;

/// <summary>A plain-text table: first column left-aligned, the others right-aligned; "-" for what does not apply.</summary>
sealed class TextTable(params string[] header)
{
    readonly List<string[]> _rows = new();

    public void Add(params string[] row) => _rows.Add(row);

    public void Write(TextWriter output)
    {
        var width = new int[header.Length];
        for (int c = 0; c < header.Length; c++) width[c] = header[c].Length;
        foreach (string[] row in _rows)
            for (int c = 0; c < row.Length && c < width.Length; c++) width[c] = Math.Max(width[c], row[c].Length);
        WriteRow(output, header, width);
        var rule = new string[header.Length];
        for (int c = 0; c < rule.Length; c++) rule[c] = new string('-', width[c]);
        WriteRow(output, rule, width);
        foreach (string[] row in _rows) WriteRow(output, row, width);
    }

    static void WriteRow(TextWriter output, string[] row, int[] width)
    {
        var sb = new StringBuilder();
        for (int c = 0; c < width.Length; c++)
        {
            string cell = c < row.Length ? row[c] : "";
            if (c > 0) sb.Append("  ");
            if (c == 0) sb.Append(cell.PadRight(width[c]));
            else sb.Append(cell.PadLeft(width[c]));
        }
        output.WriteLine(sb.ToString().TrimEnd());
    }

    /// <summary>Four significant digits, invariant culture.</summary>
    public static string Number(double v)
    {
        if (v == 0) return "0";
        double a = Math.Abs(v);
        // Whole numbers up to a billion read better without an exponent.
        return v.ToString(a >= 1e4 && a < 1e9 ? "F0" : "G4", CultureInfo.InvariantCulture);
    }

    /// <summary>Four significant digits, invariant culture.</summary>
    public static string Number(float v) => Number((double)v);

    /// <summary>Four significant digits, or "-" when the value does not apply.</summary>
    public static string Number(float? v) => v is float f ? Number((double)f) : "-";
}
