using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// Thread scaling, Fulcrum beside BepuPhysics 2 (when compiled in): `peers --scaling=1,2,4,8,16`
    /// steps every scene with each engine on each thread count, wall time for every row, and gives
    /// each row's speed-up over the same engine's 1-thread row of the same run and Bepu's mean over
    /// Fulcrum's at the same thread count. Configurations run in an order that reverses between
    /// runs and scenes, so a slow spell of a shared machine does not land on one thread count.
    /// </summary>
    public static class PeerScaling
    {
        /// <summary>Parses "1,2,4,8,16": thread counts of at least 1, or null (with a line saying why).</summary>
        public static int[]? ParseCounts(string text, TextWriter output)
        {
            var counts = new List<int>();
            foreach (string part in text.Split(','))
            {
                if (!int.TryParse(part, NumberStyles.Integer, CultureInfo.InvariantCulture, out int t) || t < 1 || t > 256)
                {
                    output.WriteLine($"--scaling needs thread counts from 1 to 256 separated by commas, got '{text}'; nothing was run.");
                    return null;
                }
                if (!counts.Contains(t)) counts.Add(t);
            }
            if (!counts.Contains(1)) counts.Insert(0, 1); // every speed-up is over the 1-thread row
            counts.Sort();
            return counts.ToArray();
        }

        /// <summary>The scenes of a scaling run: the peers pyramid and pile, and a pile four times larger.</summary>
        public static PeerScene[] Scenes(bool quick) => quick
            ? new[] { PeerScene.Pyramid(6, 10, 40), PeerScene.Pile(8, 4, 10, 40) }
            : new[] { PeerScene.Pyramid(20, 30, 150), PeerScene.PilePhases(12, 14, 30, 270, 300, 270), PeerScene.Pile(32, 8, 30, 240) };

        /// <summary>Runs the scaling table; see the class summary.</summary>
        public static void Run(TextWriter output, PeerScene[] scenes, PeerSettings settings, int[] counts, int runs, bool quick)
        {
            var configs = new List<Func<IPeerEngine>>();
            foreach (int t in counts)
            {
                int threads = t;
                configs.Add(() => new FulcrumPeer(threads));
#if PEER_BEPU
                configs.Add(() => new BepuPeer(threads));
#endif
            }
            output.WriteLine($"thread scaling: {string.Join(", ", counts)} threads; wall ms per step for every row; {Environment.ProcessorCount} logical cores");
            foreach (Func<IPeerEngine> create in configs)
                PeerRun.WarmUp(create, settings, quick ? 0.3 : 2.0, quick ? 30 : 200);

            var all = new List<List<PeerResult>>();
            for (int run = 0; run < runs; run++)
            {
                all.Add(PeerRun.MeasureRun(configs, scenes, settings, run));
                output.WriteLine($"run {run + 1} of {runs} done");
            }
            Print(output, all);
            output.WriteLine();
            output.WriteLine("Fulcrum by stage (World.LastStepProfile, wall ms per step, mean, range over runs):");
            PeerTable.PrintStages(output, all);
        }

        static void Print(TextWriter output, List<List<PeerResult>> runs)
        {
            output.WriteLine();
            output.WriteLine($"ranges over {runs.Count} run(s), lowest-highest; speed-up: the same engine's 1-thread wall mean over this row's; Bepu/Fulcrum: Bepu's wall mean over Fulcrum's at the same thread count, same run");
            output.WriteLine();
            output.WriteLine("| scene | threads | Fulcrum mean ms | median | speed-up | Bepu mean ms | median | speed-up | Bepu / Fulcrum | Fulcrum all B/step |");
            output.WriteLine("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
            List<PeerResult> first = runs[0];
            foreach (string scene in first.Select(r => r.Scene).Distinct())
            {
                foreach (int threads in first.Where(r => r.Scene == scene).Select(r => r.Threads).Distinct())
                {
                    var cells = new List<string> { scene, threads.ToString(CultureInfo.InvariantCulture) };
                    foreach (string engine in new[] { "Fulcrum", "Bepu2" })
                    {
                        var mean = new List<double>();
                        var median = new List<double>();
                        var speedUp = new List<double>();
                        foreach (List<PeerResult> run in runs)
                        {
                            PeerResult? x = Find(run, engine, scene, threads), single = Find(run, engine, scene, 1);
                            if (x == null) continue;
                            mean.Add(x.WallMeanMs);
                            median.Add(x.WallMedianMs);
                            if (single != null) speedUp.Add(single.WallMeanMs / x.WallMeanMs);
                        }
                        cells.Add(Range(mean, "F3"));
                        cells.Add(Range(median, "F3"));
                        cells.Add(Range(speedUp, "F2"));
                    }
                    var ratio = new List<double>();
                    var bytes = new List<double>();
                    foreach (List<PeerResult> run in runs)
                    {
                        PeerResult? f = Find(run, "Fulcrum", scene, threads), b = Find(run, "Bepu2", scene, threads);
                        if (f != null) bytes.Add(f.ProcessBytesPerStep);
                        if (f != null && b != null) ratio.Add(b.WallMeanMs / f.WallMeanMs);
                    }
                    cells.Add(Range(ratio, "F2"));
                    cells.Add(Range(bytes, "F0"));
                    output.WriteLine("| " + string.Join(" | ", cells) + " |");
                }
            }
        }

        static PeerResult? Find(List<PeerResult> run, string engine, string scene, int threads)
        {
            foreach (PeerResult x in run)
                if (x.Scene == scene && x.Threads == threads && x.Engine.StartsWith(engine, StringComparison.Ordinal)
                    && !x.Engine.Contains("reuse off", StringComparison.Ordinal))
                    return x;
            return null;
        }

        static string Range(List<double> values, string format)
        {
            if (values.Count == 0) return "-";
            double lo = values.Min(), hi = values.Max();
            string a = lo.ToString(format, CultureInfo.InvariantCulture), b = hi.ToString(format, CultureInfo.InvariantCulture);
            return a == b ? a : a + "-" + b;
        }
    }
}
