using System;
using System.IO;
using Fulcrum.Scenes;

namespace Fulcrum.Runner;

/// <summary>
/// <c>fulcrum run ... --save-state FILE</c> and <c>--restore-state FILE</c> (World.SaveState /
/// RestoreState): the scene is built as usual (soft bodies included), then the saved state
/// replaces it; the scene file and the flags still decide the settings, so a run restored with
/// the same scene and flags continues bit for bit where the saved run stopped.
/// </summary>
static class StateFlags
{
    /// <summary>Checks both paths before anything runs: the file to restore must exist, the one to save must not be a directory.</summary>
    public static void Check(string? restore, string? save)
    {
        if (restore != null)
        {
            if (restore.Length == 0) throw new UsageException("--restore-state: expected a file name");
            if (!File.Exists(restore)) throw new UsageException($"--restore-state: '{restore}' does not exist");
        }
        if (save != null)
        {
            if (save.Length == 0) throw new UsageException("--save-state: expected a file name");
            if (Directory.Exists(save)) throw new UsageException($"--save-state: '{save}' is a directory; give a file name such as {Path.Combine(save, "state.bin")}");
        }
    }

    /// <summary>Restores the state in <paramref name="path"/> into the built scene, keeping the scene's (and flags') settings.</summary>
    public static void Restore(SceneInstance scene, string path, TextWriter output)
    {
        World w = scene.World;
        WorldSettings settings = w.Settings;
        try
        {
            using FileStream file = File.OpenRead(path);
            if (file.Length > (1L << 30)) throw new UsageException($"--restore-state: '{path}' is {file.Length} bytes; a world state holds at most 1 GiB", Cli.ExitScene);
            w.RestoreState(file);
        }
        catch (InvalidDataException e)
        {
            throw new UsageException($"--restore-state: '{path}': {e.Message}", Cli.ExitScene);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UsageException($"--restore-state: cannot read '{path}': {e.Message}", Cli.ExitScene);
        }
        w.Settings = settings;
        output.WriteLine($"state: restored from {path} (step {w.StepIndex}, t = {SceneSetup.F((float)w.Time)} s)");
    }

    /// <summary>Writes the world's state after the run to <paramref name="path"/>.</summary>
    public static void Save(SceneInstance scene, string path, TextWriter output)
    {
        try
        {
            using (FileStream file = File.Create(path)) scene.World.SaveState(file);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new UsageException($"--save-state: cannot write '{path}': {e.Message}", Cli.ExitScene);
        }
        output.WriteLine($"state: saved to {path} ({new FileInfo(path).Length} bytes, step {scene.World.StepIndex})");
    }
}
