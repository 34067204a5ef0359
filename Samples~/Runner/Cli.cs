using System;
using System.IO;

namespace Fulcrum.Runner;

/// <summary>
/// The <c>fulcrum</c> command line (DESIGN.md, "The runner"):
/// <code>
/// fulcrum                                   the showcase report over Samples~/Scenes
/// fulcrum run SCENE.json [--seconds S | --steps N] [--dt X] [--solver pgs|tgs]
///             [--iterations N] [--substeps N] [--threads N] [--trace OUT.csv] [--every K]
///             [--save-state FILE] [--restore-state FILE]
/// fulcrum sweep SCENE.json [--solver pgs,tgs] [--iterations 1,2,4,8,16] [--substeps 1,2,4,8] [--out DIR]
///             (also --seconds S | --steps N, --dt X, --threads N)
/// fulcrum check SCENE.json
/// fulcrum run SCENE.json --record OUT.frec  a recording for the browser viewer
/// fulcrum run SCENE.json --live [--port N]  the same, streamed to the viewer while it runs
/// fulcrum view [OUT.frec] [--port N]        serves the viewer (Viewer~/dist) and the recording on localhost
/// </code>
/// Flags override the scene file. A bad scene or flag exits non-zero with one line naming
/// the flag or the field, and nothing is written.
/// </summary>
public static class Cli
{
    public const int ExitOk = 0;
    /// <summary>The scene is invalid or cannot be built.</summary>
    public const int ExitScene = 1;
    /// <summary>The command line is wrong.</summary>
    public const int ExitUsage = 2;
    /// <summary>The run finished, but a body diverged (non-finite or out of the world bounds) and was stopped; for fuzz, a world diverged or escaped.</summary>
    public const int ExitDiverged = 3;

    public const string Usage = """
        usage:
          fulcrum                          run the showcase scenes in Samples~/Scenes and print a report
          fulcrum run SCENE.json [--seconds S | --steps N] [--dt X] [--solver pgs|tgs]
                      [--iterations N] [--substeps N] [--threads N] [--trace OUT.csv] [--every K]
                      [--save-state FILE] [--restore-state FILE]
                                           save the world state after the run / restore one before it
                      [--record OUT.frec]  (a recording for 'fulcrum view'; --every K applies to it too)
                      [--live [--port N] [--viewer DIR] [--live-speed X] [--live-exit]]
                                           stream the run to the browser viewer on http://127.0.0.1:8765/
                                           at X times real time (default 1); serve until Ctrl+C, or
                                           exit when the run ends with --live-exit
          fulcrum sweep SCENE.json [--solver pgs,tgs] [--iterations 1,2,4,8,16] [--substeps 1,2,4,8] [--out DIR]
                      [--seconds S | --steps N] [--dt X] [--threads N] [--soft-solver xpbd,newton]
          fulcrum check SCENE.json         validate only: every error with its JSON path
          fulcrum fuzz [--count N] [--seed S] [--steps K] [--soft] [--verbose]
                                           run N seeded hostile worlds (--soft: soft-body worlds); list any that
                                           diverge, escape, gain energy or end inverted
          fulcrum view [OUT.frec] [--port N] [--viewer DIR]
                                           serve the browser viewer and the recording on http://127.0.0.1:8765/
        """;

    /// <summary>Runs one command line; returns the exit code. Everything printed goes to the two writers.</summary>
    public static int Run(string[] args, TextWriter output, TextWriter error)
    {
        try
        {
            if (args.Length == 0) return ReportCommand.Run(args, output);
            switch (args[0])
            {
                case "run": return RunCommand.Run(new Arguments("run", args, 1, RunCommand.Flags, RunCommand.Switches), output);
                case "check": return CheckCommand.Run(new Arguments("check", args, 1), output, error);
                case "sweep": return SweepCommand.Run(new Arguments("sweep", args, 1, SweepCommand.Flags), output);
                case "report": return ReportCommand.Run(args[1..], output);
                case "fuzz": return FuzzCommand.Run(new Arguments("fuzz", args, 1, FuzzCommand.Flags, FuzzCommand.Switches), output);
                case "view": return ViewCommand.Run(new Arguments("view", args, 1, ViewCommand.Flags), output);
                case "help" or "--help" or "-h":
                    output.WriteLine(Usage);
                    return ExitOk;
                default:
                    throw new UsageException($"unknown command '{args[0]}' (expected run, sweep, check or fuzz; 'fulcrum help' lists them)");
            }
        }
        catch (UsageException e)
        {
            error.WriteLine("fulcrum: error: " + e.Message);
            return e.ExitCode;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            error.WriteLine("fulcrum: error: " + e.Message);
            return ExitScene;
        }
    }
}
