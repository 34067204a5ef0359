using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary>
/// The default command (no arguments): runs every scene in Samples~/Scenes for a few seconds
/// of simulated time and prints one table row per scene. Scenes that cannot run yet (a shape
/// Core cannot build) get a row saying why; soft bodies and joints that are only data are
/// noted. Also <c>fulcrum report [DIR] [--seconds S]</c>.
/// </summary>
static class ReportCommand
{
    public const float DefaultSeconds = 3f;
    const string ScenesFolder = "Samples~/Scenes";

    public static int Run(string[] args, TextWriter output)
    {
        var a = new Arguments("report", args, 0, "--seconds");
        float seconds = a.PositiveFloat("--seconds") ?? DefaultSeconds;
        string dir = a.Positional.Count switch
        {
            0 => FindScenes() ?? throw new UsageException($"cannot find {ScenesFolder} above {Environment.CurrentDirectory}; run from the repository or give the folder"),
            1 => a.Positional[0],
            _ => throw new UsageException($"report: unexpected argument '{a.Positional[1]}'"),
        };
        if (!Directory.Exists(dir)) throw new UsageException($"{dir}: no such folder");
        string[] files = Directory.GetFiles(dir, "*.json");
        Array.Sort(files, StringComparer.Ordinal);

        output.WriteLine($"Fulcrum showcase: {files.Length} scenes from {dir}, {SceneSetup.F(seconds)} s each");
        output.WriteLine();
        var table = new TextTable("scene", "bodies", "joints", "steps", "ms/step", "p95", "max pen (m)", "joint err (m)", "drift (J)", "vs closed form (m)", "soft vol err", "min J");
        var notes = new List<string>();
        var clock = Stopwatch.StartNew();
        foreach (string file in files)
        {
            string name = Path.GetFileNameWithoutExtension(file);
            try
            {
                SceneDocument doc = SceneSetup.Load(file);
                SceneInstance scene = SceneSetup.Build(file, doc, WorldSettings.Default);
                ISoftBodyMonitor? soft = SoftBodySupport.Attach(scene, file, out string? softNote);
                int steps = Math.Max(1, (int)Math.Ceiling(seconds / (double)doc.Timestep - 1e-6));
                RunResult r = SceneRun.Run(scene, steps, doc.Timestep, soft);
                table.Add(name, scene.BodyHandles.Count.ToString(), scene.Joints.Count.ToString(), steps.ToString(),
                    TextTable.Number(r.MedianMs), TextTable.Number(r.P95Ms), TextTable.Number(r.MaxPenetration),
                    TextTable.Number(r.MaxJointError), TextTable.Number(r.EnergyDrift), TextTable.Number(r.ClosedFormError),
                    TextTable.Number(r.VolumeError), TextTable.Number(r.MinJ));
                if (softNote != null) notes.Add($"{name}: {softNote}");
            }
            catch (UsageException e)
            {
                table.Add(name, "-", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-");
                notes.Add($"{name}: not run: {e.Message}");
            }
        }
        table.Write(output);
        if (notes.Count > 0)
        {
            output.WriteLine();
            foreach (string n in notes) output.WriteLine("note: " + n);
        }
        output.WriteLine();
        output.WriteLine($"ms/step: median step time; p95: 95th percentile; drift: E(end) - E(0) of the dynamic bodies;");
        output.WriteLine($"vs closed form: largest distance from x0 + v0 t + g t^2/2 (scenes where every body flies free; semi-implicit Euler is g t dt/2 off).");
        output.WriteLine("soft vol err: largest |volume ratio - 1| of any soft body during the run; min J: smallest element volume ratio (negative = inverted).");
        output.WriteLine($"report took {clock.Elapsed.TotalSeconds:F1} s");
        return Cli.ExitOk;
    }

    static string? FindScenes()
    {
        foreach (string start in new[] { Environment.CurrentDirectory, AppContext.BaseDirectory })
        {
            for (DirectoryInfo? d = new DirectoryInfo(start); d != null; d = d.Parent)
            {
                string candidate = Path.Combine(d.FullName, ScenesFolder);
                if (Directory.Exists(candidate)) return Path.GetRelativePath(Environment.CurrentDirectory, candidate);
            }
        }
        return null;
    }
}
