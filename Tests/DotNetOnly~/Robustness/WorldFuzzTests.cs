using System.Collections.Generic;
using Fulcrum.Runner;
using NUnit.Framework;

namespace Fulcrum.Tests.Robustness
{
    /// <summary>
    /// The fuzz suite CI runs: seeded hostile worlds (WorldFuzz) that must either be refused by
    /// the API with an ArgumentException or run without diverging (no NaN, nothing past the
    /// world bounds: World.Diverged never fires). The failing seeds are listed one per line so
    /// each can be replayed on its own.
    /// <para>
    /// Known and not yet fixed: in about 1-2 % of these worlds a light body jointed or pressed to
    /// a much heavier one, or a thin plate spun by a joint anchor a few millimetres from its
    /// centre, is flung at up to the speed cap and ends farther than its launch speed and
    /// gravity allow (an energy gain short of divergence). That count is measured and held here
    /// as a ceiling, so it can only go down.
    /// </para>
    /// </summary>
    public class WorldFuzzTests
    {
        // Measured on seeds 0-299 (180 steps each): 0 refused, 0 diverged, 3 escaped (1 + 2:
        // seeds 106, 229, 246; 229 is a 633 kg body hanging from 0.06-0.09 kg links fixed to the
        // world, which one PGS iteration cannot hold). 4 before the speed cap also bounded the
        // velocities the relax passes leave and the reach counted launch spin (|v| + |w| r).
        // Before the speed cap was applied to the solver's velocities too, 12 of them left the
        // world bounds (flung at up to 1e5 m/s) and 19 escaped; before the hinge's swing row,
        // 10 escaped.
        [TestCase(0, 150, 1)]
        [TestCase(150, 150, 2)]
        public void Hostile_worlds_are_refused_or_never_diverge(int firstSeed, int count, int escapesMeasured)
        {
            var failures = new List<string>();
            var escapes = new List<string>();
            int refused = 0;
            for (int seed = firstSeed; seed < firstSeed + count; seed++)
            {
                WorldFuzz.Outcome o = WorldFuzz.Run(seed, 180);
                if (o.Refused) refused++;
                if (o.Failure != null) failures.Add(o.Failure);
                if (o.Escape != null) escapes.Add(o.Escape);
            }
            TestContext.Out.WriteLine($"{count} worlds: {refused} refused, {failures.Count} diverged, {escapes.Count} escaped");
            foreach (string f in failures) TestContext.Out.WriteLine("diverged: " + f);
            foreach (string e in escapes) TestContext.Out.WriteLine("escaped: " + e);
            Assert.That(failures, Is.Empty);
            Assert.That(escapes.Count, Is.LessThanOrEqualTo(escapesMeasured));
        }

        [Test]
        public void The_fuzz_command_lists_failing_worlds_and_exits_3_only_when_one_failed()
        {
            var output = new System.IO.StringWriter();
            var error = new System.IO.StringWriter();
            int code = Cli.Run(new[] { "fuzz", "--count", "30", "--seed", "0", "--steps", "120" }, output, error);
            string[] lines = output.ToString().Split('\n', System.StringSplitOptions.RemoveEmptyEntries);
            TestContext.Out.WriteLine(output.ToString());
            string last = lines[lines.Length - 1].Trim();
            Assert.That(last, Does.StartWith("fuzz: 30 worlds from seed 0, 120 steps each: "));
            int listed = lines.Length - 1;
            Assert.That(code, Is.EqualTo(listed > 0 ? Cli.ExitDiverged : Cli.ExitOk));
            foreach (string line in lines[..^1]) Assert.That(line, Does.StartWith("escaped: seed ").Or.StartWith("diverged: seed "));
            Assert.That(error.ToString(), Is.Empty);
        }
    }
}
