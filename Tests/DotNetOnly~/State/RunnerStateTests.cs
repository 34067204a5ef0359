using System;
using System.Diagnostics;
using System.IO;
using Fulcrum.Runner;
using NUnit.Framework;

namespace Fulcrum.Tests.State
{
    /// <summary>
    /// <c>fulcrum run SCENE --save-state FILE</c> and <c>--restore-state FILE</c>: a run cut in two
    /// (in this process, or continued in a fresh one) ends in the same state, byte for byte, as
    /// the run in one go; bad files and paths get one line and a non-zero exit.
    /// </summary>
    public class RunnerStateTests : Scenes.RunnerSession
    {
        string File(string name) => Path.Combine(Dir, name);


        [TestCase("ragdolls", 90)]
        [TestCase("dominoes", 120)]
        [TestCase("box-on-jelly", 40)]
        [TestCase("pinned-flag", 30)]
        public void A_run_cut_in_two_ends_where_the_whole_run_ends(string scene, int steps)
        {
            int half = steps / 2;
            Assert.That(Fulcrum("run", Scene(scene), "--steps", steps.ToString(), "--save-state", File("whole.state")).code, Is.EqualTo(0));
            Assert.That(Fulcrum("run", Scene(scene), "--steps", half.ToString(), "--save-state", File("half.state")).code, Is.EqualTo(0));
            var (code, output, error) = Fulcrum("run", Scene(scene), "--steps", (steps - half).ToString(), "--restore-state", File("half.state"), "--save-state", File("rest.state"));
            Assert.That(code, Is.EqualTo(0), error);
            Assert.That(output, Does.Contain($"state: restored from {File("half.state")} (step {half},"));
            Assert.That(output, Does.Contain($"step {steps})"));
            Assert.That(System.IO.File.ReadAllBytes(File("rest.state")), Is.EqualTo(System.IO.File.ReadAllBytes(File("whole.state"))));
        }

        [Test]
        public void A_run_continued_in_a_fresh_process_ends_where_the_whole_run_ends()
        {
            string runner = Path.Combine(TestContext.CurrentContext.TestDirectory, "fulcrum.dll");
            Assert.That(System.IO.File.Exists(runner), Is.True, runner);
            Assert.That(Fulcrum("run", Scene("box-on-jelly"), "--steps", "60", "--save-state", File("whole.state")).code, Is.EqualTo(0));
            Assert.That(Fulcrum("run", Scene("box-on-jelly"), "--steps", "25", "--save-state", File("part.state")).code, Is.EqualTo(0));

            var start = new ProcessStartInfo("dotnet")
            {
                RedirectStandardOutput = true,
                RedirectStandardError = true,
                UseShellExecute = false,
            };
            foreach (string arg in new[] { runner, "run", Scene("box-on-jelly"), "--steps", "35", "--restore-state", File("part.state"), "--save-state", File("rest.state") })
                start.ArgumentList.Add(arg);
            using Process process = Process.Start(start)!;
            string output = process.StandardOutput.ReadToEnd();
            string error = process.StandardError.ReadToEnd();
            Assert.That(process.WaitForExit(120_000), Is.True, "the runner finished");
            Assert.That(process.ExitCode, Is.EqualTo(0), output + error);
            Assert.That(System.IO.File.ReadAllBytes(File("rest.state")), Is.EqualTo(System.IO.File.ReadAllBytes(File("whole.state"))));
        }

        [Test]
        public void Bad_state_files_and_paths_get_one_line_and_a_non_zero_exit()
        {
            var missing = Fulcrum("run", Scene("pyramid"), "--steps", "5", "--restore-state", File("none.state"));
            Assert.That(missing.code, Is.EqualTo(Cli.ExitUsage));
            Assert.That(missing.error.Trim(), Does.StartWith("fulcrum: error: --restore-state:").And.Contain("does not exist"));
            Assert.That(missing.output, Is.Empty, "nothing ran");

            System.IO.File.WriteAllText(File("garbage.state"), "not a state at all, but long enough for a header of 48 bytes");
            var garbage = Fulcrum("run", Scene("pyramid"), "--steps", "5", "--restore-state", File("garbage.state"));
            Assert.That(garbage.code, Is.EqualTo(Cli.ExitScene));
            Assert.That(garbage.error.Trim(), Does.Contain("Not a Fulcrum world state"));
            Assert.That(garbage.error.Trim().Split('\n'), Has.Length.EqualTo(1));

            var directory = Fulcrum("run", Scene("pyramid"), "--steps", "5", "--save-state", Dir);
            Assert.That(directory.code, Is.EqualTo(Cli.ExitUsage));
            Assert.That(directory.error, Does.Contain("--save-state: ").And.Contain("is a directory"));

            Assert.That(Fulcrum("run", Scene("box-on-jelly"), "--steps", "5", "--save-state", File("soft.state")).code, Is.EqualTo(0));
            var mismatch = Fulcrum("run", Scene("pyramid"), "--steps", "5", "--restore-state", File("soft.state"));
            Assert.That(mismatch.code, Is.EqualTo(Cli.ExitScene));
            Assert.That(mismatch.error, Does.Contain("--restore-state: ").And.Contain("create the same soft bodies"));
        }
    }
}
