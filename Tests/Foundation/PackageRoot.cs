using System;
using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace Fulcrum.Tests
{
    /// <summary>
    /// The package folder (the one whose package.json is named com.fulcrum.physics), from
    /// which tests read Samples~/Scenes, README.md and the .meta files. Found, in order: from
    /// the environment variable FULCRUM_PACKAGE_ROOT; else walking up from the test directory
    /// and then from the current directory, at each level trying the folder itself (the
    /// repository under dotnet test), Packages/* (an embedded package in a Unity project)
    /// and Library/PackageCache/com.fulcrum.physics@* (a git or registry package; Unity's
    /// current directory is the project folder).
    /// </summary>
    static class PackageRoot
    {
        /// <summary>The package's name in package.json.</summary>
        public const string Name = "com.fulcrum.physics";

        /// <summary>Overrides the search (a package referenced from outside the Unity project with file:...).</summary>
        public const string EnvironmentVariable = "FULCRUM_PACKAGE_ROOT";

        static string? s_path;

        /// <summary>The package folder; an <see cref="AssertionException"/> if none is found.</summary>
        public static string Path => s_path ??= Find();

        /// <summary>The package's Samples~/Scenes folder.</summary>
        public static string ScenesDirectory => System.IO.Path.Combine(Path, "Samples~", "Scenes");

        static string Find() =>
            FindFrom(Environment.GetEnvironmentVariable(EnvironmentVariable), TestContext.CurrentContext.TestDirectory, Directory.GetCurrentDirectory())
            ?? throw new AssertionException($"the {Name} package folder was not found above the test directory or the current directory; set {EnvironmentVariable}");

        /// <summary>The search of <see cref="Path"/> from the given variable and start folders; null if nothing is found.</summary>
        internal static string? FindFrom(string? fromEnvironment, params string[] starts)
        {
            if (!string.IsNullOrEmpty(fromEnvironment))
            {
                if (IsPackage(fromEnvironment!)) return System.IO.Path.GetFullPath(fromEnvironment!);
                throw new AssertionException($"{EnvironmentVariable}={fromEnvironment}: no package.json of {Name} there");
            }
            foreach (string start in starts)
            {
                for (var d = new DirectoryInfo(start); d != null; d = d.Parent)
                {
                    if (IsPackage(d.FullName)) return d.FullName;
                    string packages = System.IO.Path.Combine(d.FullName, "Packages");
                    if (Directory.Exists(packages))
                        foreach (string p in Directory.GetDirectories(packages))
                            if (IsPackage(p)) return p;
                    string cache = System.IO.Path.Combine(d.FullName, "Library", "PackageCache");
                    if (Directory.Exists(cache))
                        foreach (string p in Directory.GetDirectories(cache, Name + "@*"))
                            if (IsPackage(p)) return p;
                }
            }
            return null;
        }

        static bool IsPackage(string folder)
        {
            string manifest = System.IO.Path.Combine(folder, "package.json");
            return File.Exists(manifest) && Regex.IsMatch(File.ReadAllText(manifest), "\"name\"\\s*:\\s*\"" + Regex.Escape(Name) + "\"");
        }
    }
}
