using System;
using System.IO;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary><c>fulcrum run SCENE.json [flags]</c>: runs a scene, optionally tracing it, and prints a summary table.</summary>
static class RunCommand
{
    public static readonly string[] Flags =
    {
        "--seconds", "--steps", "--dt", "--solver", "--iterations", "--substeps", "--threads", "--trace", "--every", RecordCommand.Flag,
        "--save-state", "--restore-state", "--port", "--viewer", LiveCommand.SpeedFlag,
    };

    /// <summary>Flags without a value.</summary>
    public static readonly string[] Switches = LiveCommand.Switches;

    /// <summary>Simulated time when neither --steps nor --seconds is given, s.</summary>
    public const float DefaultSeconds = 5f;

    public static int Run(Arguments a, TextWriter output, System.Threading.CancellationToken stop = default)
    {
        // Every flag and the scene are checked before anything runs or is written.
        string path = a.Scene();
        int every = a.Int("--every", 1) ?? 1;
        string? tracePath = a.String("--trace");
        if (tracePath != null && tracePath.Length == 0) throw new UsageException("--trace: expected a file name");
        if (tracePath != null && Directory.Exists(tracePath)) throw new UsageException($"--trace: '{tracePath}' is a directory; give a file name such as {Path.Combine(tracePath, "trace.csv")}");
        string? recordPath = RecordCommand.PathOf(a);
        LiveCommand.Options? live = LiveCommand.Check(a);
        if (a.Has("--every") && tracePath == null && recordPath == null && live == null) throw new UsageException("--every: only applies with --trace or --record (or --live)");
        string? restorePath = a.String("--restore-state"), savePath = a.String("--save-state");
        StateFlags.Check(restorePath, savePath);
        WorldSettings settings = SceneSetup.Settings(a);
        SceneDocument doc = SceneSetup.Load(path);
        SceneSetup.ApplySolverFlags(doc, a);
        int steps = SceneSetup.Steps(a, doc.Timestep, DefaultSeconds);
        SceneInstance scene = SceneSetup.Build(path, doc, settings);
        // Explicit --substeps/--iterations reach the soft bodies' XPBD solver too.
        ISoftBodyMonitor? soft = SoftBodySupport.Attach(scene, path, out string? softNote,
            a.Has("--substeps") ? doc.Solver.Substeps : 0, a.Has("--iterations") ? doc.Solver.Iterations : 0);

        SceneSolver s = doc.Solver;
        output.WriteLine($"scene: {path} ({CheckCommand.Count(scene.BodyHandles.Count, "body", "bodies")}, {CheckCommand.Count(scene.Joints.Count, "joint", "joints")}, {CheckCommand.Count(scene.SoftBodies.Count, "soft body", "soft bodies")})");
        output.WriteLine($"solver: {SceneNames.Of(s.Type)}, {s.Iterations} iterations" +
                         (s.Type == SolverType.Tgs ? $" x {s.Substeps} substeps" : "") +
                         $", dt {SceneSetup.F(doc.Timestep)} s, {steps} steps ({SceneSetup.F(steps * doc.Timestep)} s), threads {settings.Threads}");
        if (softNote != null) output.WriteLine("note: " + softNote);
        if (restorePath != null) StateFlags.Restore(scene, restorePath, output);

        using LiveServer? server = live != null ? LiveCommand.Start(live, output) : null;
        using TraceWriter? trace = tracePath != null ? OpenTrace(tracePath, scene, soft) : null;
        RunResult result;
        string? recordingSummary = null;
        using (RecordCommand.Session? recording = recordPath != null || server != null ? RecordCommand.Open(recordPath, scene, steps, every, server) : null)
        {
            Action<int>? afterStep = recording?.AfterStep;
            if (live != null) afterStep = LiveCommand.Paced(afterStep, doc.Timestep, live.Speed);
            result = SceneRun.Run(scene, steps, doc.Timestep, soft, trace, every, afterStep);
            recordingSummary = recording?.Summary();
        }
        server?.End();
        if (trace != null) output.WriteLine($"trace: {trace.BodyPath}, {trace.WorldPath}" + (trace.SoftPath != null ? $", {trace.SoftPath}" : ""));
        if (recordingSummary != null) output.WriteLine(recordingSummary);

        output.WriteLine();
        var table = new TextTable("steps", "ms/step median", "ms/step p95", "max penetration (m)", "max joint error (m)",
            "energy drift (J)", "soft volume error", "min J");
        table.Add(result.Steps.ToString(), TextTable.Number(result.MedianMs), TextTable.Number(result.P95Ms),
            TextTable.Number(result.MaxPenetration), TextTable.Number(result.MaxJointError), TextTable.Number(result.EnergyDrift),
            TextTable.Number(result.VolumeError), TextTable.Number(result.MinJ));
        table.Write(output);
        if (savePath != null) StateFlags.Save(scene, savePath, output);
        int code = ReportDivergence(scene, output);
        if (server != null) LiveCommand.Finish(server, live!, output, stop);
        return code;
    }

    /// <summary>
    /// One line and <see cref="Cli.ExitDiverged"/> when a body of the run diverged (the world
    /// stopped it; see World.Diverged), naming the last one, its step and what happened.
    /// </summary>
    public static int ReportDivergence(SceneInstance scene, TextWriter output)
    {
        World w = scene.World;
        SoftBodies.SoftBodySystem? soft = SoftBodies.SoftBodySystem.Of(w);
        if (soft != null && soft.DivergenceCount > 0)
            output.WriteLine($"diverged: {soft.DivergenceCount} time(s); last: soft body {soft.LastDiverged} became non-finite, left the world bounds or blew apart in step {soft.LastDivergedStep} and was put back at rest");
        if (w.DivergenceCount == 0) return soft != null && soft.DivergenceCount > 0 ? Cli.ExitDiverged : Cli.ExitOk;
        Divergence d = w.LastDivergence;
        string name = $"#{d.Body.Index}";
        for (int k = 0; k < scene.BodyHandles.Count; k++)
            if (scene.BodyHandles[k].Equals(d.Body)) name = $"'{scene.BodyName(k)}'";
        string what = d.Kind == DivergenceKind.NonFinite ? "became non-finite" : $"left the world bounds (+-{Limits.MaxPosition:G} m)";
        output.WriteLine($"diverged: {w.DivergenceCount} time(s); last: body {name} {what} in step {d.Step} and was stopped");
        return Cli.ExitDiverged;
    }

    // The trace files, or a one-line reason naming the flag and the path.
    static TraceWriter OpenTrace(string path, SceneInstance scene, ISoftBodyMonitor? soft)
    {
        try
        {
            return new TraceWriter(path, scene, soft);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new UsageException($"--trace: cannot write '{path}': {e.Message}");
        }
    }
}
