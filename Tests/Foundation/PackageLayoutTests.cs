using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>
    /// The repository is a Unity package: Unity ignores any asset without a .meta file in an
    /// immutable (git or registry) package, so a missing one silently drops code in Unity.
    /// </summary>
    public class PackageLayoutTests
    {
        static string Root() => PackageRoot.Path;

        static bool HiddenFromUnity(string relative) =>
            relative.Split(Path.DirectorySeparatorChar).Any(p => p.StartsWith(".", StringComparison.Ordinal) || p.EndsWith("~", StringComparison.Ordinal) || p == "bin" || p == "obj");

        [Test]
        public void Every_file_and_folder_Unity_imports_has_a_meta_file()
        {
            string root = Root();
            var missing = Directory.EnumerateFileSystemEntries(root, "*", SearchOption.AllDirectories)
                .Select(p => Path.GetRelativePath(root, p))
                .Where(r => !HiddenFromUnity(r) && !r.EndsWith(".meta", StringComparison.Ordinal))
                .Where(r => !File.Exists(Path.Combine(root, r + ".meta")))
                .ToList();
            Assert.That(missing, Is.Empty, "run: bash Tools~/generate-meta.sh");
        }

        [Test]
        public void Meta_guids_are_unique()
        {
            string root = Root();
            var guids = Directory.EnumerateFiles(root, "*.meta", SearchOption.AllDirectories)
                .Where(p => !HiddenFromUnity(Path.GetRelativePath(root, p)))
                .Select(p => File.ReadLines(p).First(l => l.StartsWith("guid:", StringComparison.Ordinal)))
                .ToList();
            Assert.That(guids, Is.Unique);
        }

        [Test]
        public void Runtime_assemblies_never_name_UnityEngine_outside_the_adapter()
        {
            string root = Root();
            foreach (string folder in new[] { "Core", "SoftBodies", "Components" })
            {
                var offenders = Directory.EnumerateFiles(Path.Combine(root, "Runtime", folder), "*.cs", SearchOption.AllDirectories)
                    .Where(f => File.ReadLines(f).Any(l => l.TrimStart().StartsWith("using UnityEngine", StringComparison.Ordinal)))
                    .ToList();
                Assert.That(offenders, Is.Empty, folder);
                string asmdef = File.ReadAllText(Directory.EnumerateFiles(Path.Combine(root, "Runtime", folder), "*.asmdef").Single());
                Assert.That(asmdef, Does.Contain("\"noEngineReferences\": true"), folder);
            }
        }
    }
}
