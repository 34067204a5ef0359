using System.IO;

namespace Fulcrum.Runner;

/// <summary>
/// <c>fulcrum fuzz [--count N] [--seed S] [--steps K]</c>: runs N seeded hostile worlds
/// (<see cref="WorldFuzz"/>) from seed S, K steps each, and prints one line per world that
/// diverged, flung a body farther than its speeds allow, or gained more mechanical energy than
/// its motors and correction passes may add, then a summary. Exits 3 when any did.
/// </summary>
static class FuzzCommand
{
    public static readonly string[] Flags = { "--count", "--seed", "--steps" };

    public static int Run(Arguments a, TextWriter output)
    {
        int count = a.Int("--count", 1) ?? 1000;
        int seed = a.Int("--seed", 0) ?? 0;
        int steps = a.Int("--steps", 1) ?? 180;
        int diverged = 0, escaped = 0, gained = 0, refused = 0;
        for (int s = seed; s < seed + count; s++)
        {
            WorldFuzz.Outcome o = WorldFuzz.Run(s, steps);
            if (o.Refused) refused++;
            if (o.Failure != null)
            {
                diverged++;
                output.WriteLine("diverged: " + o.Failure);
            }
            else if (o.Escape != null)
            {
                escaped++;
                output.WriteLine("escaped: " + o.Escape);
            }
            else if (o.EnergyGain != null)
            {
                gained++;
                output.WriteLine("energy: " + o.EnergyGain);
            }
        }
        output.WriteLine($"fuzz: {count} worlds from seed {seed}, {steps} steps each: {refused} refused, {diverged} diverged, {escaped} escaped, {gained} gained energy");
        return diverged + escaped + gained > 0 ? Cli.ExitDiverged : Cli.ExitOk;
    }
}
