using System.IO;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>
    /// PackageRoot finds the package where Unity keeps it, so that the scene tests also run in
    /// Unity's Test Runner: embedded under Packages/, or in Library/PackageCache for a git or
    /// registry package, seen from inside the project (Unity's current directory).
    /// </summary>
    public class PackageRootTests
    {
        string _project = "";

        [SetUp]
        public void MakeProject()
        {
            _project = Path.Combine(Path.GetTempPath(), "fulcrum-project-" + System.Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Path.Combine(_project, "Library", "ScriptAssemblies"));
            Directory.CreateDirectory(Path.Combine(_project, "Packages", "com.other.thing"));
            File.WriteAllText(Path.Combine(_project, "Packages", "com.other.thing", "package.json"), "{ \"name\": \"com.other.thing\" }");
        }

        [TearDown]
        public void RemoveProject() => Directory.Delete(_project, recursive: true);

        string Package(params string[] parts)
        {
            string folder = Path.Combine(_project, Path.Combine(parts));
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, "package.json"), "{\n  \"name\": \"com.fulcrum.physics\",\n  \"version\": \"0.3.0\"\n}");
            return folder;
        }

        [Test]
        public void An_embedded_package_is_found_from_inside_the_project()
        {
            string package = Package("Packages", "com.fulcrum.physics");
            Assert.That(PackageRoot.FindFrom(null, Path.Combine(_project, "Library", "ScriptAssemblies")), Is.EqualTo(package));
        }

        [Test]
        public void A_git_package_is_found_in_the_package_cache()
        {
            string package = Package("Library", "PackageCache", "com.fulcrum.physics@0a1b2c3d4e");
            Assert.That(PackageRoot.FindFrom(null, _project), Is.EqualTo(package));
        }

        [Test]
        public void The_environment_variable_wins_and_a_wrong_one_is_an_error()
        {
            string package = Package("Elsewhere", "fulcrum");
            Package("Packages", "com.fulcrum.physics");
            Assert.That(PackageRoot.FindFrom(package, _project), Is.EqualTo(Path.GetFullPath(package)));
            Assert.That(() => PackageRoot.FindFrom(Path.Combine(_project, "Library"), _project), Throws.InstanceOf<AssertionException>());
        }

        [Test]
        public void Nothing_is_found_in_a_project_without_the_package()
        {
            Assert.That(PackageRoot.FindFrom(null, Path.Combine(_project, "Library")), Is.Null.Or.Not.StartWith(_project));
        }
    }
}
