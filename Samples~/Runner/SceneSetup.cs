using System;
using System.Globalization;
using System.IO;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary>Loading a scene file and applying the command line's overrides, with one-line reasons on failure.</summary>
static class SceneSetup
{
    /// <summary>A scene file's text; a missing or unreadable file becomes a one-line <see cref="UsageException"/>.</summary>
    public static string ReadText(string path)
    {
        try
        {
            return SceneFile.ReadText(path);
        }
        catch (FileNotFoundException)
        {
            throw new UsageException($"{path}: no such scene file", Cli.ExitScene);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UsageException($"{path}: cannot read: {e.Message}", Cli.ExitScene);
        }
    }

    /// <summary>Reads and validates a scene; a problem becomes a <see cref="UsageException"/> naming the file and the field.</summary>
    public static SceneDocument Load(string path)
    {
        string text = ReadText(path);
        try
        {
            return SceneFile.Parse(text);
        }
        catch (SceneException e)
        {
            string more = e.Errors.Count > 1 ? $" (and {e.Errors.Count - 1} more: see 'fulcrum check {path}')" : "";
            throw new UsageException($"{path}: {e.Errors[0]}{more}", Cli.ExitScene);
        }
    }

    /// <summary>--dt, --solver, --iterations and --substeps override the scene's values.</summary>
    public static void ApplySolverFlags(SceneDocument doc, Arguments a)
    {
        if (a.FloatInRange("--dt", Limits.MinTimeStep, Limits.MaxTimeStep, "Limits.MinTimeStep/MaxTimeStep") is float dt) doc.Timestep = dt;
        if (a.Solver("--solver") is SolverType solver) doc.Solver.Type = solver;
        if (a.Int("--iterations", 1, Limits.MaxIterations, "Limits.MaxIterations") is int iterations) doc.Solver.Iterations = iterations;
        if (a.Int("--substeps", 1, Limits.MaxSubsteps, "Limits.MaxSubsteps") is int substeps) doc.Solver.Substeps = substeps;
    }

    /// <summary>Steps from --steps or --seconds (not both), else <paramref name="defaultSeconds"/>.</summary>
    public static int Steps(Arguments a, float dt, float defaultSeconds)
    {
        int? steps = a.Int("--steps", 1);
        float? seconds = a.PositiveFloat("--seconds");
        if (steps != null && seconds != null) throw new UsageException("--steps: give --steps or --seconds, not both");
        if (steps is int n) return n;
        double count = Math.Ceiling((seconds ?? defaultSeconds) / (double)dt - 1e-6);
        if (count > int.MaxValue)
            throw new UsageException(seconds != null
                ? $"--seconds: {seconds} s is too many steps of {F(dt)} s"
                : $"timestep: {F(dt)} s needs more than {int.MaxValue} steps for the default {defaultSeconds} s (set $.timestep or --dt, or give --steps)");
        return Math.Max(1, (int)count);
    }

    /// <summary>World settings with the --threads flag (the scene sets the rest).</summary>
    public static WorldSettings Settings(Arguments a)
    {
        WorldSettings s = WorldSettings.Default;
        if (a.Int("--threads", 1, Limits.MaxThreads, "Limits.MaxThreads") is int threads) s.Threads = threads;
        return s;
    }

    /// <summary>Builds the scene; a shape Core cannot build yet becomes a one-line reason naming its path.</summary>
    public static SceneInstance Build(string path, SceneDocument doc, WorldSettings settings)
    {
        try
        {
            return SceneBuilder.Build(doc, settings);
        }
        catch (SceneException e)
        {
            throw new UsageException($"{path}: {e.Errors[0]}", Cli.ExitScene);
        }
    }

    public static string F(float f) => f.ToString("R", CultureInfo.InvariantCulture);
}
