using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// World.SaveState / RestoreState: the size of the state and what writing and reading it
    /// costs, next to one step of the same world, on sample scenes (rigid, jointed, soft).
    /// </summary>
    public sealed class StateBenchmark : IBenchmark
    {
        public string Name => "state";

        public string Description => "World.SaveState / RestoreState: state size, save and restore ms beside one step, on sample scenes";

        public void Run(TextWriter output, bool quick)
        {
            int reps = quick ? 3 : 15;
            output.WriteLine($"After 60 steps of each scene; save into / restore from a MemoryStream, {reps} repetitions (each restore is");
            output.WriteLine("followed by one step, timed as 'step'). Mean, median and [min-max] in ms; the machine may be shared.");
            output.WriteLine();
            output.WriteLine("| scene | bodies | soft bodies | state KiB | save ms mean / median [range] | restore ms mean / median [range] | step ms median |");
            output.WriteLine("|---|---:|---:|---:|---|---|---:|");
            string dir = ScenesDir();
            foreach (string name in new[] { "pyramid-40", "tower-100", "ragdolls", "box-on-jelly", "jelly-stack" })
                Row(output, dir, name, reps);
        }

        static void Row(TextWriter output, string dir, string name, int reps)
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Load(Path.Combine(dir, name + ".json")));
            if (scene.Document.SoftBodies.Count > 0) SceneSoftBodyBuilder.Build(scene, directory: dir);
            World w = scene.World;
            for (int i = 0; i < 60; i++) w.Step(scene.Timestep);
            var save = new List<double>();
            var restore = new List<double>();
            var step = new List<double>();
            long size = 0;
            var stream = new MemoryStream();
            for (int r = 0; r < reps; r++)
            {
                stream.SetLength(0);
                long t = Stopwatch.GetTimestamp();
                w.SaveState(stream);
                save.Add(Ms(t));
                size = stream.Length;
                stream.Position = 0;
                t = Stopwatch.GetTimestamp();
                w.RestoreState(stream);
                restore.Add(Ms(t));
                t = Stopwatch.GetTimestamp();
                w.Step(scene.Timestep);
                step.Add(Ms(t));
            }
            output.WriteLine($"| {name} | {w.BodyCount} | {w.SoftBodyCount()} | {size / 1024.0:F0} | {Stats(save)} | {Stats(restore)} | {Median(step):F2} |");
        }

        static double Ms(long since) => (Stopwatch.GetTimestamp() - since) * 1000.0 / Stopwatch.Frequency;

        static double Median(List<double> v)
        {
            var s = v.OrderBy(x => x).ToList();
            return s.Count % 2 == 1 ? s[s.Count / 2] : 0.5 * (s[s.Count / 2 - 1] + s[s.Count / 2]);
        }

        static string Stats(List<double> v) => $"{v.Average():F2} / {Median(v):F2} [{v.Min():F2}-{v.Max():F2}]";

        static string ScenesDir()
        {
            for (var d = new DirectoryInfo(AppContext.BaseDirectory); d != null; d = d.Parent)
            {
                string candidate = Path.Combine(d.FullName, "Samples~", "Scenes");
                if (Directory.Exists(candidate)) return candidate;
            }
            throw new DirectoryNotFoundException("Samples~/Scenes not found above " + AppContext.BaseDirectory);
        }
    }
}
