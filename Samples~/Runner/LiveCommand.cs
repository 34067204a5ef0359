using System;
using System.Diagnostics;
using System.IO;
using System.Threading;

namespace Fulcrum.Runner;

/// <summary>
/// <c>fulcrum run SCENE.json --live [--port N] [--viewer DIR] [--live-speed X] [--live-exit]</c>:
/// the run streams its recording to open browser viewers while it runs
/// (<see cref="LiveServer"/>), paced at X times real time (default 1). When the run ends the
/// server keeps serving the finished recording until Ctrl+C, or, with <c>--live-exit</c>,
/// exits once every connected viewer has been sent the whole recording (for scripts and tests).
/// Documentation~/Runner.md lists the flags.
/// </summary>
static class LiveCommand
{
    /// <summary>The switch that turns live mode on.</summary>
    public const string Flag = "--live";

    /// <summary>The switch that ends the command with the run.</summary>
    public const string ExitFlag = "--live-exit";

    /// <summary>Simulated seconds per wall-clock second.</summary>
    public const string SpeedFlag = "--live-speed";

    /// <summary>Flags with a value that only apply with --live.</summary>
    public static readonly string[] ValueFlags = { "--port", "--viewer", SpeedFlag };

    /// <summary>Valueless flags.</summary>
    public static readonly string[] Switches = { Flag, ExitFlag };

    /// <summary>How long --live-exit waits for slow viewers to take the rest of the recording.</summary>
    static readonly TimeSpan ExitGrace = TimeSpan.FromSeconds(10);

    /// <summary>The checked live flags.</summary>
    public sealed record Options(int? Port, string Viewer, float Speed, bool Exit);

    /// <summary>The live flags, checked before anything runs; null without --live.</summary>
    public static Options? Check(Arguments a)
    {
        if (!a.Has(Flag))
        {
            foreach (string f in ValueFlags)
                if (a.Has(f)) throw new UsageException($"{f}: only applies with {Flag}");
            if (a.Has(ExitFlag)) throw new UsageException($"{ExitFlag}: only applies with {Flag}");
            return null;
        }
        int? port = a.Int("--port", 1, 65535, "a TCP port");
        float speed = a.FloatInRange(SpeedFlag, 0.01f, 1000f, "times real time") ?? 1f;
        string viewer = ViewCommand.FindViewer(a.String("--viewer"));
        return new Options(port, viewer, speed, a.Has(ExitFlag));
    }

    /// <summary>Starts the server and prints the page to open.</summary>
    public static LiveServer Start(Options o, TextWriter output)
    {
        var server = new LiveServer(o.Viewer, o.Port);
        output.WriteLine($"live: {server.Url}  (open it in a browser; the run goes at {o.Speed:G} x real time)");
        output.Flush();
        return server;
    }

    /// <summary>
    /// <paramref name="inner"/> followed by a wait that holds step n back until n dt / speed
    /// wall-clock seconds after the first step: real time at speed 1. A run slower than
    /// that simply does not wait.
    /// </summary>
    public static Action<int> Paced(Action<int>? inner, float dt, float speed)
    {
        var clock = Stopwatch.StartNew();
        double secondsPerStep = dt / speed;
        return n =>
        {
            inner?.Invoke(n);
            double ahead = n * secondsPerStep - clock.Elapsed.TotalSeconds;
            if (ahead > 0.001) Thread.Sleep(TimeSpan.FromSeconds(ahead));
        };
    }

    /// <summary>After the run (the server has been told it ended): exit, or serve until Ctrl+C or <paramref name="stop"/>.</summary>
    public static void Finish(LiveServer server, Options o, TextWriter output, CancellationToken stop = default)
    {
        if (o.Exit)
        {
            if (!server.WaitForViewers(ExitGrace)) output.WriteLine("live: a viewer did not take the whole recording in time");
            return;
        }
        output.WriteLine($"live: run finished; still serving {server.Url}  (Ctrl+C to stop)");
        output.Flush();
        using var done = new ManualResetEventSlim();
        ConsoleCancelEventHandler onCtrlC = (_, e) => { e.Cancel = true; done.Set(); };
        Console.CancelKeyPress += onCtrlC;
        try { done.Wait(stop); }
        catch (OperationCanceledException) { }
        finally { Console.CancelKeyPress -= onCtrlC; }
    }
}
