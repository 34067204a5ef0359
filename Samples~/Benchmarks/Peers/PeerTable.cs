using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// Prints the peers table: one run's figures, or with several runs each figure's lowest and
    /// highest value over the runs (ratios are taken within a run, then ranged).
    /// </summary>
    public static class PeerTable
    {
        /// <summary>Prints <paramref name="runs"/> (each a list of rows in the same order).</summary>
        public static void Print(TextWriter output, List<List<PeerResult>> runs)
        {
            var table = new List<string[]>
            {
                new[] { "engine", "scene", "bodies", "clock", "mean ms", "median ms", "p95 ms", "x Fulcrum", "speed-up", "proc cpu ms", "B/step", "all B/step", "drift mm", "sink mm", "ground pen mm", "speed mm/s", "finite" },
            };
            List<PeerResult> first = runs[0];
            for (int r = 0; r < first.Count; r++)
            {
                PeerResult row = first[r];
                var ratio = new List<double>();
                var speedUp = new List<double>();
                bool finite = true;
                foreach (List<PeerResult> run in runs)
                {
                    PeerResult x = run[r];
                    finite &= x.Finite;
                    PeerResult? reference = Find(run, "Fulcrum", x.Scene);
                    if (reference != null)
                        ratio.Add(x.CpuTime == reference.CpuTime ? x.MeanMs / reference.MeanMs : x.WallMeanMs / reference.WallMeanMs);
                    if (x.Threads > 1)
                    {
                        PeerResult? single = Find(run, BaseName(x.Engine), x.Scene);
                        if (single != null) speedUp.Add(single.WallMeanMs / x.WallMeanMs);
                    }
                }
                table.Add(new[]
                {
                    row.Engine, row.Scene, row.Bodies.ToString(CultureInfo.InvariantCulture), row.CpuTime ? "cpu" : "wall",
                    Range(runs, r, x => x.MeanMs, "F3"), Range(runs, r, x => x.MedianMs, "F3"), Range(runs, r, x => x.P95Ms, "F3"),
                    Range(ratio, "F2"), Range(speedUp, "F2"), Range(runs, r, x => x.ProcessCpuMs, "F3"),
                    Range(runs, r, x => x.BytesPerStep, "F0"), Range(runs, r, x => x.ProcessBytesPerStep, "F0"),
                    Range(runs, r, x => x.Drift * 1000, "F1"), Range(runs, r, x => x.Sink * 1000, "F1"),
                    Range(runs, r, x => x.MaxGroundPenetration * 1000, "F1"), Range(runs, r, x => x.EndSpeed * 1000, "F1"),
                    finite ? "yes" : "NO",
                });
            }
            Write(output, table);
        }

        static void Write(TextWriter output, List<string[]> table)
        {
            var widths = new int[table[0].Length];
            foreach (string[] line in table)
                for (int c = 0; c < line.Length; c++) widths[c] = Math.Max(widths[c], line[c].Length);
            foreach (string[] line in table)
            {
                var text = new StringBuilder();
                for (int c = 0; c < line.Length; c++)
                    text.Append(c < 2 ? line[c].PadRight(widths[c] + 2) : line[c].PadLeft(widths[c]) + "  ");
                output.WriteLine(text.ToString().TrimEnd());
            }
        }

        /// <summary>
        /// Fulcrum's rows split by stage (World.LastStepProfile: wall time inside the step, mean
        /// ms per step), ranged over runs like the main table.
        /// </summary>
        public static void PrintStages(TextWriter output, List<List<PeerResult>> runs)
        {
            var header = new List<string> { "engine", "scene" };
            for (int stage = 0; stage < StepProfile.StageCount; stage++) header.Add(((StepStage)stage).ToString());
            var table = new List<string[]> { header.ToArray() };
            List<PeerResult> first = runs[0];
            for (int r = 0; r < first.Count; r++)
            {
                if (first[r].StageMs == null) continue;
                var line = new List<string> { first[r].Engine, first[r].Scene };
                for (int stage = 0; stage < StepProfile.StageCount; stage++)
                {
                    int s = stage;
                    line.Add(Range(runs, r, x => x.StageMs![s], "F3"));
                }
                table.Add(line.ToArray());
            }
            Write(output, table);
        }

        // "Fulcrum 2 threads" -> "Fulcrum": the same engine's 1-thread row.
        static string BaseName(string engine)
        {
            int cut = engine.LastIndexOf(' ');
            if (cut > 0 && engine.EndsWith(" threads", StringComparison.Ordinal))
                cut = engine.LastIndexOf(' ', cut - 1);
            return cut > 0 ? engine.Substring(0, cut) : engine;
        }

        internal static PeerResult? Find(List<PeerResult> run, string engine, string scene)
        {
            foreach (PeerResult x in run)
                if (x.Engine == engine && x.Scene == scene) return x;
            return null;
        }

        static string Range(List<List<PeerResult>> runs, int row, Func<PeerResult, double> value, string format)
        {
            var values = new List<double>();
            foreach (List<PeerResult> run in runs) values.Add(value(run[row]));
            return Range(values, format);
        }

        static string Range(List<double> values, string format)
        {
            double lo = double.PositiveInfinity, hi = double.NegativeInfinity;
            foreach (double v in values)
            {
                if (double.IsNaN(v)) continue;
                lo = Math.Min(lo, v);
                hi = Math.Max(hi, v);
            }
            if (lo > hi) return "-";
            string a = lo.ToString(format, CultureInfo.InvariantCulture), b = hi.ToString(format, CultureInfo.InvariantCulture);
            return a == b ? a : a + "-" + b;
        }
    }
}
