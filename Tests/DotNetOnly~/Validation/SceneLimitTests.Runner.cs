using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text;
using Fulcrum.Runner;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Validation
{
    // The tests of SceneLimitTests that need the runner (Samples~/Runner) or .NET-only APIs: net10 only
    // (this folder ends in '~', so Unity never compiles it); the rest is in Tests/.
    public partial class SceneLimitTests
    {
        static (int code, string output, string error) Fulcrum(params string[] args)
        {
            var output = new StringWriter();
            var error = new StringWriter();
            int code = Cli.Run(args, output, error);
            return (code, output.ToString(), error.ToString());
        }

        static void AssertOneLine(string error, params string[] mustContain)
        {
            string text = error.TrimEnd('\n', '\r');
            Assert.That(text, Does.Not.Contain("\n"), "one line");
            Assert.That(text, Does.Not.Contain("   at "), "no stack trace");
            Assert.That(text.Length, Is.LessThan(700));
            foreach (string s in mustContain) Assert.That(text, Does.Contain(s));
        }

        [Test]
        public void Non_regular_and_huge_files_are_refused_before_reading()
        {
            if (!OperatingSystem.IsLinux()) Assert.Ignore("needs /dev/zero");
            var watch = Stopwatch.StartNew();
            Assert.That(() => SceneFile.ReadText("/dev/zero"), Throws.InstanceOf<IOException>().With.Message.Contains("not a regular file"));
            Assert.That(() => SceneFile.ReadText(_dir), Throws.InstanceOf<IOException>().With.Message.Contains("directory"));
            Assert.That(() => SceneFile.ReadText(Path.Combine(_dir, "none.json")), Throws.InstanceOf<FileNotFoundException>());
            string big = Path.Combine(_dir, "big.json");
            using (var f = new FileStream(big, FileMode.Create)) f.SetLength(SceneFile.MaxFileBytes + 1); // sparse
            Assert.That(() => SceneFile.ReadText(big), Throws.InstanceOf<IOException>().With.Message.Contains("SceneFile.MaxFileBytes"));
            Assert.That(watch.Elapsed.TotalSeconds, Is.LessThan(2));

            var r = Fulcrum("check", "/dev/zero");
            Assert.That(r.code, Is.EqualTo(Cli.ExitScene));
            AssertOneLine(r.error, "/dev/zero", "not a regular file");
        }

        [Test]
        public void Missing_devices_and_garbage_mesh_files_get_one_line_naming_file_and_line()
        {
            string material = "\"material\": { \"youngsModulus\": 1e5, \"poissonRatio\": 0.3, \"density\": 1000 }, \"position\": [0, 1, 0]";
            string Scene(string mesh) => Write("soft.json", "{" + Head + ", \"bodies\": [], \"softBodies\": [{ \"name\": \"j\", \"mesh\": " + mesh + ", " + material + " }] }");

            Write("bad.node", "4 3 0 0\n1 0 0 0\n2 1 0 zz\n3 0 1 0\n4 0 0 1\n");
            Write("ok.ele", "1 4 0\n1 1 2 3 4\n");
            var r = Fulcrum("run", Scene("{ \"type\": \"tetgen\", \"node\": \"bad.node\", \"ele\": \"ok.ele\" }"), "--steps", "1");
            Assert.That(r.code, Is.EqualTo(Cli.ExitScene));
            AssertOneLine(r.error, "$.softBodies[0].mesh.node", "bad.node", "line 3");

            r = Fulcrum("run", Scene("{ \"type\": \"tetgen\", \"node\": \"bad.node\", \"ele\": \"missing.ele\" }"), "--steps", "1");
            Assert.That(r.code, Is.EqualTo(Cli.ExitScene));
            AssertOneLine(r.error, "$.softBodies[0].mesh.ele", "missing.ele", "no such file");

            Write("garbage.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
            r = Fulcrum("run", Scene("{ \"type\": \"obj\", \"file\": \"garbage.obj\", \"thickness\": 0.01 }"), "--steps", "1");
            Assert.That(r.code, Is.EqualTo(Cli.ExitScene));
            AssertOneLine(r.error, "$.softBodies[0].mesh.file", "garbage.obj", "line 4");

            if (OperatingSystem.IsLinux())
            {
                r = Fulcrum("run", Scene("{ \"type\": \"obj\", \"file\": \"/dev/zero\", \"thickness\": 0.01 }"), "--steps", "1");
                Assert.That(r.code, Is.EqualTo(Cli.ExitScene));
                AssertOneLine(r.error, "$.softBodies[0].mesh.file", "/dev/zero");
            }
        }

        [Test]
        public void Runner_flags_are_capped_and_named()
        {
            string scene = Write("ok.json", "{" + Head + ", \"bodies\": [{ \"name\": \"b\", \"type\": \"dynamic\", \"shape\": { \"type\": \"sphere\", \"radius\": 0.5 } }] }");
            var r = Fulcrum("run", scene, "--steps", "1", "--threads", "1000000");
            Assert.That(r.code, Is.Not.EqualTo(0));
            AssertOneLine(r.error, "--threads", "Limits.MaxThreads");
            r = Fulcrum("run", scene, "--steps", "1", "--substeps", "1000000000");
            AssertOneLine(r.error, "--substeps");
            r = Fulcrum("run", scene, "--dt", "1e-30");
            AssertOneLine(r.error, "--dt");
            r = Fulcrum("run", scene, "--steps", "1", "--trace", _dir);
            Assert.That(r.code, Is.Not.EqualTo(0));
            AssertOneLine(r.error, "--trace", _dir, "directory");
            string blocked = Write("file", "x");
            r = Fulcrum("run", scene, "--steps", "1", "--trace", Path.Combine(blocked, "t.csv"));
            Assert.That(r.code, Is.Not.EqualTo(0));
            AssertOneLine(r.error, "--trace", blocked);
            r = Fulcrum("sweep", scene, "--steps", "1", "--out", blocked);
            AssertOneLine(r.error, "--out", blocked);
        }

        [Test]
        public void A_tiny_timestep_in_the_scene_names_the_timestep_not_a_flag()
        {
            string scene = Write("dt.json", "{\"format\": \"fulcrum-scene/1\", \"timestep\": 1e-30, \"bodies\": []}");
            var r = Fulcrum("run", scene);
            Assert.That(r.code, Is.EqualTo(Cli.ExitScene));
            AssertOneLine(r.error, "$.timestep");
            Assert.That(r.error, Does.Not.Contain("--seconds"));
        }
    }
}
