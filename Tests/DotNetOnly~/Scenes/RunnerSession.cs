using System;
using System.IO;
using Fulcrum.Runner;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    /// <summary>
    /// What the command-line tests share: a fresh temporary folder per test (<see cref="Dir"/>),
    /// the sample scenes by name, and <c>fulcrum</c> run in this process with its exit code and
    /// both outputs captured.
    /// </summary>
    public abstract class RunnerSession
    {
        /// <summary>This test's temporary folder, removed after it.</summary>
        protected string Dir { get; private set; } = "";

        [SetUp]
        public void MakeTempDir()
        {
            Dir = Path.Combine(Path.GetTempPath(), "fulcrum-test-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Dir);
        }

        [TearDown]
        public void RemoveTempDir() => Directory.Delete(Dir, recursive: true);

        /// <summary>Samples~/Scenes/NAME.json, found above the test directory.</summary>
        protected static string Scene(string name) => Path.Combine(RigidScenes.RigidSceneFiles.ScenesDirectory, name + ".json");

        /// <summary>Runs <c>fulcrum ARGS</c> in this process.</summary>
        protected static (int code, string output, string error) Fulcrum(params string[] args)
        {
            var output = new StringWriter();
            var error = new StringWriter();
            int code = Cli.Run(args, output, error);
            return (code, output.ToString(), error.ToString());
        }
    }
}
