using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// Fulcrum beside BepuPhysics 2 and Jitter2 (whichever were compiled in) in one process, on the
    /// same box scenes with matched step, substeps and iterations: ms per step and the same
    /// accuracy figures for each, so speed is compared at equal accuracy.
    /// Options: --substeps=S --iterations=I (default: Fulcrum's defaults).
    /// </summary>
    public sealed class PeersBenchmark : IBenchmark
    {
        public string Name => "peers";

        public string Description => "Fulcrum vs BepuPhysics 2 / Jitter2 (opt-in builds): tower, pyramid, pile; ms/step and drift";

        public void Run(TextWriter output, bool quick)
        {
            int? substeps = Option("--substeps=", WorldSettings.Default.Substeps, output);
            int? iterations = Option("--iterations=", WorldSettings.Default.Iterations, output);
            if (substeps == null || iterations == null) return;
            var settings = new PeerSettings { Substeps = substeps.Value, Iterations = iterations.Value };
            PeerScene[] scenes = quick
                ? new[] { PeerScene.Tower(20, 30, 120), PeerScene.Pyramid(6, 10, 60), PeerScene.Pile(5, 4, 10, 60) }
                : new[] { PeerScene.Tower(20, 60, 600), PeerScene.Pyramid(20, 30, 270), PeerScene.Pile(12, 14, 30, 270) };

            string? hint = PeerRoster.MissingHint();
            if (hint != null) output.WriteLine(hint);
            output.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"matched: dt 1/60 s, {settings.Substeps} substeps x {settings.Iterations} iterations, relax {settings.RelaxIterations} (Fulcrum, Jitter2), Fulcrum block solver {(WorldSettings.Default.BlockSolver ? "on" : "off")}, friction {settings.Friction}, 1 kg unit cubes, contact {settings.ContactHertz} Hz / damping ratio {settings.ContactDampingRatio} / push-out {settings.MaxPushSpeed} m/s (Fulcrum, Bepu), no sleeping, no damping, 1 thread"));
            output.WriteLine(ThreadClock.IsCpuTime
                ? "ms/step, p95: the stepping thread's CPU time (median, 95th percentile of timed steps); wall ms: median wall time; x Fulcrum: ms/step over Fulcrum's"
                : "ms/step, p95: wall time (median, 95th percentile of timed steps); x Fulcrum: ms/step over Fulcrum's");
            output.WriteLine("drift: top box's x/z distance from its start at the end; sink: its start y - end y; ground pen: deepest corner below the ground over the run");

            IReadOnlyList<Func<IPeerEngine>> engines = PeerRoster.Engines();
            var versions = new List<string>();
            foreach (Func<IPeerEngine> create in engines)
            {
                double warm = PeerRun.WarmUp(create, settings, quick ? 0.5 : 3.0, quick ? 60 : 300);
                using IPeerEngine engine = create();
                versions.Add(string.Create(CultureInfo.InvariantCulture, $"{engine.Name} {engine.Version} (warm-up {warm:F1} s)"));
            }
            output.WriteLine("engines: " + string.Join(", ", versions));
            var rows = new List<PeerResult>();
            foreach (PeerScene scene in scenes)
                foreach (Func<IPeerEngine> create in engines)
                    rows.Add(PeerRun.Measure(create(), scene, settings));
            Print(output, rows);
        }

        static void Print(TextWriter output, List<PeerResult> rows)
        {
            var table = new List<string[]>
            {
                new[] { "engine", "scene", "bodies", "ms/step", "p95 ms", "wall ms", "x Fulcrum", "alloc B/step", "drift mm", "sink mm", "ground pen mm", "finite" },
            };
            double fulcrumMs = double.NaN;
            foreach (PeerResult r in rows)
            {
                if (r.Engine == "Fulcrum") fulcrumMs = r.MedianMs;
                table.Add(new[]
                {
                    r.Engine, r.Scene, r.Bodies.ToString(CultureInfo.InvariantCulture),
                    Format(r.MedianMs, "F3"), Format(r.P95Ms, "F3"), Format(r.WallMedianMs, "F3"), Format(r.MedianMs / fulcrumMs, "F2"), Format(r.BytesPerStep, "F0"),
                    Format(r.Drift * 1000, "F1"), Format(r.Sink * 1000, "F1"), Format(r.MaxGroundPenetration * 1000, "F1"),
                    r.Finite ? "yes" : "NO",
                });
            }
            var widths = new int[table[0].Length];
            foreach (string[] row in table)
                for (int c = 0; c < row.Length; c++) widths[c] = Math.Max(widths[c], row[c].Length);
            foreach (string[] row in table)
            {
                var line = new System.Text.StringBuilder();
                for (int c = 0; c < row.Length; c++)
                    line.Append(c < 2 ? row[c].PadRight(widths[c] + 2) : row[c].PadLeft(widths[c]) + "  ");
                output.WriteLine(line.ToString().TrimEnd());
            }
        }

        static string Format(double value, string format) =>
            double.IsNaN(value) ? "-" : value.ToString(format, CultureInfo.InvariantCulture);

        // Program passes every "--" argument through untouched, so options ride along as --name=value.
        // A bad value prints one line and returns null: nothing runs.
        static int? Option(string prefix, int fallback, TextWriter output)
        {
            foreach (string arg in Environment.GetCommandLineArgs())
                if (arg.StartsWith(prefix, StringComparison.Ordinal))
                {
                    if (int.TryParse(arg.AsSpan(prefix.Length), NumberStyles.Integer, CultureInfo.InvariantCulture, out int value) && value >= 1)
                        return value;
                    output.WriteLine($"{prefix}N needs an integer >= 1, got '{arg}'; nothing was run.");
                    return null;
                }
            return fallback;
        }
    }
}
