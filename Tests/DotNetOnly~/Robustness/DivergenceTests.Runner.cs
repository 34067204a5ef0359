using System;
using System.IO;
using System.Numerics;
using Fulcrum.Runner;
using Fulcrum.SoftBodies;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Robustness
{
    // The tests of DivergenceTests that need the runner (Samples~/Runner) or .NET-only APIs: net10 only
    // (this folder ends in '~', so Unity never compiles it); the rest is in Tests/.
    public partial class DivergenceTests
    {
        [Test]
        public void The_runner_exits_3_with_one_line_when_a_body_leaves_the_world()
        {
            string dir = Path.Combine(Path.GetTempPath(), "fulcrum-diverge-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string path = Path.Combine(dir, "escape.json");
                File.WriteAllText(path, @"{
  ""format"": ""fulcrum-scene/1"",
  ""gravity"": [0, 0, 0],
  ""bodies"": [
    {""name"": ""runaway"", ""shape"": {""type"": ""sphere"", ""radius"": 0.5}, ""position"": [99990, 0, 0], ""velocity"": [400, 0, 0]}
  ]
}");
                var output = new StringWriter();
                var error = new StringWriter();
                int code = Cli.Run(new[] { "run", path, "--seconds", "1" }, output, error);
                string[] lines = output.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries);
                TestContext.Out.WriteLine(output.ToString());
                Assert.That(code, Is.EqualTo(Cli.ExitDiverged));
                Assert.That(lines[lines.Length - 1], Does.StartWith("diverged: 1 time(s); last: body 'runaway' left the world bounds"));
            }
            finally
            {
                Directory.Delete(dir, recursive: true);
            }
        }
    }
}
