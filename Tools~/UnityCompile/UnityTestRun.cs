using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Reflection;

namespace Fulcrum.UnityCompile;

/// <summary>
/// Runs the test assembly exactly as <see cref="UnityLikeCompiler"/> built it (C# 9 against
/// .NET Standard 2.1 and NUnit 3.6, with the Runtime assemblies built the same way, so without
/// their <c>#if NET</c> paths) on .NET with VSTest and the NUnit adapter: the closest this
/// machine gets to Unity's Test Runner, which runs the same binary under Mono. Opt-in
/// (<c>--run-tests</c>): it takes several minutes, the Runtime being built without its
/// .NET-only fast paths.
/// </summary>
static class UnityTestRun
{
    static string Metadata(string key) =>
        typeof(UnityTestRun).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>().Single(a => a.Key == key).Value
        ?? throw new InvalidOperationException(key);

    /// <summary>Stages the compiled assemblies with the adapter and a test host under <paramref name="compiled"/>/run and runs VSTest; returns its exit code.</summary>
    public static int Run(string root, string compiled, string[] vstestArguments)
    {
        string packages = Metadata("NuGetPackageRoot");
        string run = Path.Combine(compiled, "run");
        if (Directory.Exists(run)) Directory.Delete(run, recursive: true);
        Directory.CreateDirectory(run);
        foreach (string dll in Directory.GetFiles(compiled, "*.dll")) Copy(dll, run);
        // The binary was compiled against NUnit 3.6.0's .NET Framework build (Unity's NUnit is a
        // .NET Framework build too); on .NET the same version's .NET Standard build stands in.
        Copy(Path.Combine(packages, "nunit", Metadata("NUnitVersion"), "lib", "netstandard1.6", "nunit.framework.dll"), run);
        foreach (string folder in new[]
        {
            Path.Combine(packages, "nunit3testadapter", Metadata("AdapterVersion"), "build", "netcoreapp3.1"),
            Path.Combine(packages, "microsoft.testplatform.testhost", Metadata("TestPlatformVersion"), "lib", "netcoreapp3.1"),
            Path.Combine(packages, "microsoft.testplatform.objectmodel", Metadata("TestPlatformVersion"), "lib", "netcoreapp3.1"),
            Path.Combine(packages, "newtonsoft.json", Metadata("NewtonsoftVersion"), "lib", "netstandard2.0"),
        })
            foreach (string dll in Directory.GetFiles(folder, "*.dll")) Copy(dll, run);
        File.WriteAllText(Path.Combine(run, "Fulcrum.Tests.runtimeconfig.json"),
            "{ \"runtimeOptions\": { \"tfm\": \"net10.0\", \"rollForward\": \"LatestMajor\", \"framework\": { \"name\": \"Microsoft.NETCore.App\", \"version\": \"10.0.0\" } } }");

        var start = new ProcessStartInfo("dotnet") { UseShellExecute = false, WorkingDirectory = run };
        start.ArgumentList.Add("vstest");
        start.ArgumentList.Add(Path.Combine(run, "Fulcrum.Tests.dll"));
        start.ArgumentList.Add("--TestAdapterPath:" + run);
        foreach (string a in vstestArguments) start.ArgumentList.Add(a);
        // The staged folder is not inside the package: tell PackageRoot where it is.
        start.Environment["FULCRUM_PACKAGE_ROOT"] = root;
        using Process process = Process.Start(start) ?? throw new InvalidOperationException("could not start dotnet vstest");
        process.WaitForExit();
        return process.ExitCode;
    }

    static void Copy(string file, string folder) => File.Copy(file, Path.Combine(folder, Path.GetFileName(file)), overwrite: true);
}
