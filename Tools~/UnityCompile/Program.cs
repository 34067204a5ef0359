using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace Fulcrum.UnityCompile;

/// <summary>
/// The CI's stand-in for Unity's script compilation. It finds every .asmdef Unity would
/// import from this package (the package folder, and each sample of package.json as if
/// imported into Assets), and compiles each as its own assembly with
/// <see cref="UnityLikeCompiler"/>, in reference order, against the other assemblies' outputs,
/// the UnityEngine/UnityEditor stubs of Tests/UnityCompileCheck~ (plus, from SampleStubs/,
/// the few types only the samples use that those stubs lack), and NUnit for asmdefs that
/// list nunit.framework.dll.
/// Exit code 0 when every assembly compiled without a warning. With --run-tests, then runs
/// the test assembly so compiled (<see cref="UnityTestRun"/>; arguments after it go to
/// dotnet vstest, e.g. --TestCaseFilter:FullyQualifiedName~Scenes).
/// Usage: dotnet run --project Tools~/UnityCompile [-- [PACKAGE_ROOT] [--run-tests [VSTEST ARGS]]]
/// </summary>
static class Program
{
    const string PackageName = "com.fulcrum.physics";

    static int Main(string[] args)
    {
        int runAt = Array.IndexOf(args, "--run-tests");
        string[] own = runAt >= 0 ? args.Take(runAt).ToArray() : args;
        string root = own.Length > 0 ? Path.GetFullPath(own[0]) : FindPackageRoot(Directory.GetCurrentDirectory());
        string compiled = Path.Combine(root, ".artifacts", "unity-compile");
        var compiler = new UnityLikeCompiler(compiled);
        int failures = 0;

        var orphans = new List<string>();
        var assemblies = UnityScriptFolders.Discover(root, orphans);
        foreach (string sample in SamplePaths(root))
        {
            var sampleOrphans = new List<string>();
            assemblies.AddRange(UnityScriptFolders.Discover(Path.Combine(root, sample), sampleOrphans));
            orphans.AddRange(sampleOrphans);
        }
        foreach (string orphan in orphans)
        {
            Console.WriteLine($"FAILED {Path.GetRelativePath(root, orphan)}: no .asmdef above it (Unity would put it in Assembly-CSharp or skip it)");
            failures++;
        }
        foreach (var clash in assemblies.GroupBy(a => a.Name).Where(g => g.Count() > 1))
        {
            Console.WriteLine($"FAILED two .asmdef files named {clash.Key}");
            failures++;
        }

        // The UnityEngine/UnityEditor stand-ins (not ours to warn about: compiled without -warnaserror).
        string stubs = "UnityEngine";
        string sharedStubs = Path.Combine(root, "Tests", "UnityCompileCheck~", "UnityEngineStubs.cs");
        var stubSources = new List<string> { sharedStubs };
        // SampleStubs/NAME.cs declares type NAME, needed only while the shared stubs lack it.
        string shared = File.ReadAllText(sharedStubs);
        foreach (string extra in Directory.GetFiles(Path.Combine(root, "Tools~", "UnityCompile", "SampleStubs"), "*.cs").OrderBy(f => f, StringComparer.Ordinal))
            if (!Regex.IsMatch(shared, @"\b(class|struct|enum|interface)\s+" + Regex.Escape(Path.GetFileNameWithoutExtension(extra)) + @"\b"))
                stubSources.Add(extra);
        var (stubsOk, stubsOutput) = compiler.Compile(stubs, stubSources, Array.Empty<string>(), null, allowUnsafe: false, warningsAsErrors: false);
        if (!stubsOk)
        {
            Console.WriteLine($"FAILED the UnityEngine stubs:\n{stubsOutput}");
            return 1;
        }

        var done = new Dictionary<string, bool>();
        foreach (AsmdefAssembly a in InReferenceOrder(assemblies))
        {
            string rel = Path.GetRelativePath(root, a.AsmdefPath);
            var unmet = a.DefineConstraints.Where(c => c.StartsWith("!", StringComparison.Ordinal) ? UnityLikeCompiler.Defines.Contains(c.Substring(1)) : !UnityLikeCompiler.Defines.Contains(c)).ToList();
            if (unmet.Count > 0)
            {
                Console.WriteLine($"skipped {a.Name} ({rel}): define constraints not met: {string.Join(", ", unmet)}");
                continue;
            }
            var references = new List<string>();
            var notes = new List<string>();
            bool blocked = false;
            foreach (string reference in a.References)
            {
                AsmdefAssembly? target = Resolve(assemblies, reference);
                if (target == null)
                {
                    if (reference.StartsWith("Unity", StringComparison.Ordinal)) { notes.Add($"{reference}: Unity's, not stubbed"); continue; }
                    Console.WriteLine($"FAILED {a.Name} ({rel}): reference {reference} names no .asmdef");
                    blocked = true;
                    continue;
                }
                if (!done.TryGetValue(target.Name, out bool ok) || !ok) { blocked = true; notes.Add($"{target.Name} failed"); continue; }
                references.Add(compiler.OutputOf(target.Name));
            }
            if (!a.NoEngineReferences) references.Add(compiler.OutputOf(stubs));
            foreach (string pre in a.PrecompiledReferences)
            {
                if (pre == "nunit.framework.dll") { references.Add(compiler.NUnitFramework); notes.Add($"NUnit {compiler.NUnitVersion}"); }
                else { Console.WriteLine($"FAILED {a.Name} ({rel}): precompiled reference {pre} is unknown here"); blocked = true; }
            }
            if (a.PrecompiledReferences.Contains("nunit.framework.dll"))
                foreach (string problem in NUnit35.Check(a.Sources))
                {
                    Console.WriteLine($"FAILED {a.Name}: {Path.GetRelativePath(root, problem)}");
                    blocked = true;
                }
            if (blocked)
            {
                Console.WriteLine($"FAILED {a.Name} ({rel}): not compiled ({string.Join("; ", notes)})");
                done[a.Name] = false;
                failures++;
                continue;
            }
            if (a.ResponseFile is string rsp) notes.Add("csc.rsp: " + string.Join(" ", UnityLikeCompiler.ReadResponseFile(rsp)));
            var (success, output) = compiler.Compile(a.Name, a.Sources, references, a.ResponseFile, a.AllowUnsafeCode, warningsAsErrors: true);
            done[a.Name] = success;
            string summary = $"{a.Name} ({rel}, {a.Sources.Count} scripts{(notes.Count > 0 ? "; " + string.Join("; ", notes) : "")})";
            if (success) Console.WriteLine($"ok     {summary}");
            else
            {
                failures++;
                Console.WriteLine($"FAILED {summary}");
            }
            if (output.Length > 0) Console.WriteLine(output.Replace(root + Path.DirectorySeparatorChar, ""));
        }
        Console.WriteLine(failures == 0
            ? $"{done.Count} assemblies compiled as Unity would (C# 9, .NET Standard 2.1, csc.rsp, warnings as errors)"
            : $"{failures} problem(s); {done.Count(d => d.Value)} of {assemblies.Count} assemblies compiled");
        if (failures > 0) return 1;
        return runAt >= 0 ? UnityTestRun.Run(root, compiled, args.Skip(runAt + 1).ToArray()) : 0;
    }

    static AsmdefAssembly? Resolve(List<AsmdefAssembly> assemblies, string reference) =>
        reference.StartsWith("GUID:", StringComparison.Ordinal)
            ? assemblies.FirstOrDefault(a => a.Guid == reference.Substring(5))
            : assemblies.FirstOrDefault(a => a.Name == reference);

    /// <summary>Depth-first: every assembly after the ones it references (a cycle is reported by the compile that lacks its reference).</summary>
    static List<AsmdefAssembly> InReferenceOrder(List<AsmdefAssembly> assemblies)
    {
        var order = new List<AsmdefAssembly>();
        var seen = new HashSet<string>();
        void Visit(AsmdefAssembly a)
        {
            if (!seen.Add(a.Name)) return;
            foreach (string r in a.References)
                if (Resolve(assemblies, r) is AsmdefAssembly t) Visit(t);
            order.Add(a);
        }
        foreach (AsmdefAssembly a in assemblies) Visit(a);
        return order;
    }

    static IEnumerable<string> SamplePaths(string root)
    {
        using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(Path.Combine(root, "package.json")));
        if (!doc.RootElement.TryGetProperty("samples", out JsonElement samples)) return Array.Empty<string>();
        return samples.EnumerateArray().Select(s => s.GetProperty("path").GetString()!).ToList();
    }

    /// <summary>The nearest folder at or above <paramref name="start"/> whose package.json names this package.</summary>
    static string FindPackageRoot(string start)
    {
        for (string? dir = start; dir != null; dir = Path.GetDirectoryName(dir))
        {
            string manifest = Path.Combine(dir, "package.json");
            if (File.Exists(manifest) && File.ReadAllText(manifest).Contains($"\"{PackageName}\"", StringComparison.Ordinal)) return dir;
        }
        throw new DirectoryNotFoundException($"no package.json of {PackageName} at or above {start}");
    }
}
