using System.IO;

namespace Fulcrum.Runner;

/// <summary>
/// <c>fulcrum fuzz [--count N] [--seed S] [--steps K] [--soft] [--verbose]</c>: runs N seeded hostile worlds
/// (<see cref="WorldFuzz"/>, or with <c>--soft</c> soft-body worlds, <see cref="SoftFuzz"/>)
/// from seed S, K steps each, and prints one line per world that diverged, flung a body
/// farther than its speeds allow, gained more energy than its motors and correction passes
/// may add, or (soft) ended with an inverted element, then a summary. Exits 3 when any did.
/// </summary>
static class FuzzCommand
{
    public static readonly string[] Flags = { "--count", "--seed", "--steps" };
    public static readonly string[] Switches = { "--soft", "--verbose" };

    public static int Run(Arguments a, TextWriter output)
    {
        int count = a.Int("--count", 1) ?? 1000;
        int seed = a.Int("--seed", 0) ?? 0;
        int steps = a.Int("--steps", 1) ?? 180;
        bool soft = a.Has("--soft"), verbose = a.Has("--verbose");
        int diverged = 0, escaped = 0, gained = 0, refused = 0, inverted = 0, retried = 0;
        for (int s = seed; s < seed + count; s++)
        {
            string? failure, escape, gain, inversion = null;
            if (soft)
            {
                SoftFuzz.Outcome o = SoftFuzz.Run(s, steps);
                if (o.Refused)
                {
                    refused++;
                    if (verbose) output.WriteLine("refused: " + o.Refusal);
                }
                (failure, escape, gain, inversion) = (o.Failure, o.Escape, o.EnergyGain, o.Inverted);
                retried += o.Retried;
                if (verbose && o.Retried > 0) output.WriteLine($"retried: seed {s}: {o.Retried} step(s) taken again with finer substeps");
            }
            else
            {
                WorldFuzz.Outcome o = WorldFuzz.Run(s, steps);
                if (o.Refused) refused++;
                (failure, escape, gain) = (o.Failure, o.Escape, o.EnergyGain);
            }
            if (failure != null)
            {
                diverged++;
                output.WriteLine("diverged: " + failure);
            }
            else if (escape != null)
            {
                escaped++;
                output.WriteLine("escaped: " + escape);
            }
            else if (gain != null)
            {
                gained++;
                output.WriteLine("energy: " + gain);
            }
            else if (inversion != null)
            {
                inverted++;
                output.WriteLine("inverted: " + inversion);
            }
        }
        output.WriteLine($"fuzz: {count} {(soft ? "soft " : "")}worlds from seed {seed}, {steps} steps each: {refused} refused, {diverged} diverged, {escaped} escaped, {gained} gained energy" + (soft ? $", {inverted} inverted ({retried} steps taken again with finer substeps)" : ""));
        return diverged + escaped + gained + inverted > 0 ? Cli.ExitDiverged : Cli.ExitOk;
    }
}
