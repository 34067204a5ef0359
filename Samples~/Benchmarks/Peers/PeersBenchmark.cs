using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// Fulcrum beside BepuPhysics 2 and Jitter2 (whichever were compiled in) in one process, on the
    /// same box scenes with matched step, substeps and iterations: mean, median and p95 ms per
    /// step and the same accuracy figures for each, so speed is compared at equal accuracy.
    /// Rows: Fulcrum (the ratio column's reference), Fulcrum with manifold reuse off, Fulcrum and
    /// Bepu on --threads threads, Bepu and Jitter2 on one. The pile is timed in two phases
    /// (collapse, settled heap). Each run measures every row of a scene before the next scene,
    /// in an order that alternates between runs and scenes, so a slow spell of a loaded machine
    /// does not land on one engine; with --runs=N the summary gives each figure's range over runs.
    /// Options (--name=value or --name value): --runs=N (default 1), --threads=T (default 2), --substeps=S --iterations=I
    /// --relax=R (default: Fulcrum's defaults; relax passes apply to Fulcrum and Jitter2),
    /// --scene=NAME (only the scenes whose name starts with NAME: tower, pyramid, pile),
    /// --scaling=1,2,4,8,16 (instead of the table: Fulcrum and Bepu on each thread count, see <see cref="PeerScaling"/>).
    /// </summary>
    public sealed class PeersBenchmark : IBenchmark
    {
        public string Name => "peers";

        public string Description => "Fulcrum vs BepuPhysics 2 / Jitter2 (opt-in builds): tower, pyramid, pile collapse/settled; mean/median/p95 ms, bytes, drift; --runs=N";

        public void Run(TextWriter output, bool quick)
        {
            int? substeps = Option("--substeps=", WorldSettings.Default.Substeps, output);
            int? iterations = Option("--iterations=", WorldSettings.Default.Iterations, output);
            int? runs = Option("--runs=", 1, output);
            int? threads = Option("--threads=", 2, output);
            int? relax = Option("--relax=", WorldSettings.Default.RelaxIterations, output, min: 0);
            if (substeps == null || iterations == null || runs == null || threads == null || relax == null) return;
            var settings = new PeerSettings { Substeps = substeps.Value, Iterations = iterations.Value, RelaxIterations = relax.Value };
            PeerScene[] scenes = quick
                ? new[] { PeerScene.Tower(20, 30, 120), PeerScene.Pyramid(6, 10, 60), PeerScene.PilePhases(5, 4, 10, 60, 60, 60) }
                : new[] { PeerScene.Tower(20, 60, 600), PeerScene.Pyramid(20, 30, 270), PeerScene.PilePhases(12, 14, 30, 270, 300, 270) };

            string? scaling = TextOption("--scaling=");
            if (scaling != null)
            {
                int[]? counts = PeerScaling.ParseCounts(scaling, output);
                if (counts == null) return;
                string? missing = PeerRoster.MissingHint();
                if (missing != null) output.WriteLine(missing);
                PeerScaling.Run(output, PeerScaling.Scenes(quick), settings, counts, runs.Value, quick);
                return;
            }

            string? only = TextOption("--scene=");
            if (only != null)
            {
                scenes = Array.FindAll(scenes, scene => scene.Name.StartsWith(only, StringComparison.Ordinal));
                if (scenes.Length == 0)
                {
                    output.WriteLine($"--scene={only} names no scene (tower, pyramid, pile); nothing was run.");
                    return;
                }
            }
            string? hint = PeerRoster.MissingHint();
            if (hint != null) output.WriteLine(hint);
            output.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"matched: dt 1/60 s, {settings.Substeps} substeps x {settings.Iterations} iterations, relax {settings.RelaxIterations} (Fulcrum, Jitter2), Fulcrum block solver {(WorldSettings.Default.BlockSolver ? "on" : "off")}, friction {settings.Friction}, 1 kg unit cubes, contact {settings.ContactHertz} Hz / damping ratio {settings.ContactDampingRatio} / push-out {settings.MaxPushSpeed} m/s (Fulcrum, Bepu), no sleeping, no damping"));
            output.WriteLine(ThreadClock.IsCpuTime
                ? "clock: 1-thread rows (cpu) time the stepping thread's CPU time, so time slices lost to other processes are not counted; rows on several threads (wall) time wall time"
                : "clock: wall time for every row");
            output.WriteLine("mean/median/p95: of the timed steps; x Fulcrum: mean over the Fulcrum row's mean on the same clock (1-thread rows: CPU; threaded rows: wall), same run;");
            output.WriteLine("speed-up: the same engine's 1-thread wall mean over this row's wall mean; proc cpu ms: CPU time of all the process's threads per step (mean); B/step: bytes the stepping thread allocated per step; all B/step: the whole process (runtime background threads too)");
            output.WriteLine("drift: top box's x/z distance from its start at the phase's end; sink: its start y - end y; ground pen: deepest corner below the ground in the phase; speed: mean box speed in the phase's last step");

            IReadOnlyList<Func<IPeerEngine>> engines = PeerRoster.Engines(threads.Value);
            var versions = new List<string>();
            foreach (Func<IPeerEngine> create in engines)
            {
                double warm = PeerRun.WarmUp(create, settings, quick ? 0.5 : 3.0, quick ? 60 : 300);
                using IPeerEngine engine = create();
                versions.Add(string.Create(CultureInfo.InvariantCulture, $"{engine.Name} {engine.Version} (warm-up {warm:F1} s)"));
            }
            output.WriteLine("engines: " + string.Join(", ", versions));
            var all = new List<List<PeerResult>>();
            for (int run = 0; run < runs.Value; run++)
            {
                List<PeerResult> rows = PeerRun.MeasureRun(engines, scenes, settings, run);
                all.Add(rows);
                if (runs.Value > 1)
                {
                    output.WriteLine();
                    output.WriteLine($"run {run + 1} of {runs.Value}:");
                }
                PeerTable.Print(output, new List<List<PeerResult>> { rows });
            }
            if (runs.Value > 1)
            {
                output.WriteLine();
                output.WriteLine($"ranges over {runs.Value} runs (lowest-highest):");
                PeerTable.Print(output, all);
            }
            output.WriteLine();
            output.WriteLine("Fulcrum by stage (World.LastStepProfile, wall ms per step, mean" + (runs.Value > 1 ? ", range over runs" : "") + "):");
            PeerTable.PrintStages(output, all);
            output.WriteLine();
            PeerBars.Print(output, all);
        }

        // Program passes every "--" argument (and every number) through untouched, so options ride along.
        // A bad value prints one line and returns null: nothing runs.
        // "--name=value", or "--name value" (prefix is "--name=").
        static string? TextOption(string prefix)
        {
            string[] args = Environment.GetCommandLineArgs();
            for (int i = 0; i < args.Length; i++)
            {
                if (args[i].StartsWith(prefix, StringComparison.Ordinal)) return args[i].Substring(prefix.Length);
                if (args[i] == prefix.TrimEnd('=') && i + 1 < args.Length) return args[i + 1];
            }
            return null;
        }

        static int? Option(string prefix, int fallback, TextWriter output, int min = 1)
        {
            string? text = TextOption(prefix);
            if (text == null) return fallback;
            if (int.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out int value) && value >= min)
                return value;
            output.WriteLine($"{prefix}N needs an integer >= {min}, got '{text}'; nothing was run.");
            return null;
        }
    }
}
