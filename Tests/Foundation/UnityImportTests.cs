using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>
    /// Importing the package or one of its samples into a Unity project compiles without an
    /// error or a warning (issue 13, item 3): what can be checked from the files. The compile
    /// itself is Tools~/UnityCompile's CI check.
    /// </summary>
    public class UnityImportTests
    {
        static JsonValue Manifest() => JsonParser.Parse(File.ReadAllText(Path.Combine(PackageRoot.Path, "package.json")));

        static List<string> SamplePaths() => Manifest()["samples"]!.Items.Select(s => s["path"]!.AsString).ToList();

        [Test]
        public void The_samples_list_holds_only_the_Unity_ready_samples()
        {
            Assert.That(SamplePaths(), Is.EqualTo(new[] { "Samples~/Scenes", "Samples~/ComponentsSample", "Samples~/BridgeSample" }));
        }

        [Test]
        public void Each_sample_has_an_asmdef_and_a_MonoBehaviour_and_no_project_file()
        {
            foreach (string sample in SamplePaths())
            {
                string folder = Path.Combine(PackageRoot.Path, sample);
                var files = Directory.GetFiles(folder, "*", SearchOption.AllDirectories);
                Assert.That(files.Count(f => f.EndsWith(".asmdef", StringComparison.Ordinal)), Is.EqualTo(1), sample);
                Assert.That(files.Where(f => f.EndsWith(".csproj", StringComparison.Ordinal) || f.EndsWith(".sln", StringComparison.Ordinal)), Is.Empty, sample);
                Assert.That(files.Where(f => f.EndsWith(".cs", StringComparison.Ordinal)).Any(f => File.ReadAllText(f).Contains(": MonoBehaviour")), Is.True, sample + " has a MonoBehaviour");
            }
        }

        [Test]
        public void Every_package_asmdef_turns_on_the_nullable_context_in_its_csc_rsp()
        {
            // Unity compiles with nullable off: the '?' annotations would each warn (CS8632) on import.
            string root = PackageRoot.Path;
            var asmdefs = new[] { "Runtime", "Editor", "Tests" }
                .SelectMany(d => Directory.GetFiles(Path.Combine(root, d), "*.asmdef", SearchOption.AllDirectories))
                .Where(f => !Path.GetRelativePath(root, f).Split(Path.DirectorySeparatorChar).Any(p => p.EndsWith("~", StringComparison.Ordinal)))
                .ToList();
            Assert.That(asmdefs, Has.Count.GreaterThanOrEqualTo(6));
            foreach (string asmdef in asmdefs)
            {
                string rsp = Path.Combine(Path.GetDirectoryName(asmdef)!, "csc.rsp");
                Assert.That(File.Exists(rsp), Is.True, rsp);
                Assert.That(File.ReadAllText(rsp), Does.Contain("-nullable:enable"), rsp);
            }
        }

        [Test]
        public void Unity_physics_module_is_a_dependency_when_the_adapter_uses_ForceMode()
        {
            string root = PackageRoot.Path;
            bool usesForceMode = new[] { Path.Combine(root, "Runtime", "Unity"), Path.Combine(root, "Editor") }
                .SelectMany(d => Directory.GetFiles(d, "*.cs", SearchOption.AllDirectories))
                .Any(f => File.ReadAllText(f).Contains("UnityEngine.ForceMode"));
            JsonValue? dependencies = Manifest()["dependencies"];
            if (usesForceMode)
                Assert.That(dependencies?["com.unity.modules.physics"], Is.Not.Null, "UnityEngine.ForceMode lives in Unity's physics module");
        }
    }
}
