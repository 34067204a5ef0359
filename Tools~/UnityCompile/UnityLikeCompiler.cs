using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Reflection;

namespace Fulcrum.UnityCompile;

/// <summary>
/// Runs the SDK's Roslyn csc on one assembly with what Unity's editor passes: C# 9, the .NET
/// Standard 2.1 reference assemblies (API Compatibility Level ".NET Standard 2.1"), the
/// editor's scripting defines, the asmdef's references, and the csc.rsp next to the asmdef.
/// Nullable is left at the compiler default (off), as Unity leaves it; warnings are errors.
/// </summary>
sealed class UnityLikeCompiler
{
    readonly string _csc;
    readonly string[] _frameworkReferences;
    readonly string _outputFolder;

    /// <summary>The NUnit framework assembly given to asmdefs that list nunit.framework.dll.</summary>
    public string NUnitFramework { get; }
    public string NUnitVersion { get; }

    /// <summary>Unity 2021.3's editor defines that code might test (the UNITY_x_y_OR_NEWER ladder, editor, tests, profile).</summary>
    public static readonly IReadOnlyList<string> Defines = BuildDefines();

    public UnityLikeCompiler(string outputFolder)
    {
        _outputFolder = outputFolder;
        _csc = Path.Combine(Metadata("RoslynDirectory"), "bincore", "csc.dll");
        string netstandard = Metadata("NetStandardReferences");
        NUnitFramework = Metadata("NUnitFramework");
        NUnitVersion = Metadata("NUnitVersion");
        foreach (string path in new[] { _csc, netstandard, NUnitFramework })
            if (!File.Exists(path) && !Directory.Exists(path)) throw new FileNotFoundException($"not found: {path} (run 'dotnet restore' on Tools~/UnityCompile)");
        _frameworkReferences = Directory.GetFiles(netstandard, "*.dll").OrderBy(f => f, StringComparer.Ordinal).ToArray();
        Directory.CreateDirectory(outputFolder);
    }

    static string Metadata(string key) =>
        typeof(UnityLikeCompiler).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>().Single(a => a.Key == key).Value
        ?? throw new InvalidOperationException(key);

    static List<string> BuildDefines()
    {
        var d = new List<string> { "UNITY_EDITOR", "UNITY_INCLUDE_TESTS", "DEBUG", "TRACE", "ENABLE_MONO", "NET_STANDARD", "NET_STANDARD_2_1", "NETSTANDARD", "NETSTANDARD2_1", "CSHARP_7_3_OR_NEWER", "UNITY_2021_3" };
        for (int minor = 3; minor <= 6; minor++) d.Add($"UNITY_5_{minor}_OR_NEWER");
        for (int year = 2017; year <= 2021; year++)
            for (int minor = 1; minor <= (year == 2021 ? 3 : year == 2020 ? 3 : 4); minor++) d.Add($"UNITY_{year}_{minor}_OR_NEWER");
        return d;
    }

    /// <summary>The path of the compiled assembly <paramref name="name"/>.</summary>
    public string OutputOf(string name) => Path.Combine(_outputFolder, name + ".dll");

    /// <summary>Compiles <paramref name="sources"/> into <paramref name="name"/>.dll; returns the compiler's output and whether it succeeded.</summary>
    public (bool ok, string output) Compile(string name, IEnumerable<string> sources, IEnumerable<string> references, string? responseFile, bool allowUnsafe, bool warningsAsErrors)
    {
        var args = new List<string>
        {
            "-nologo", "-nostdlib+", "-target:library", "-langversion:9.0", "-deterministic", "-debug-",
            $"-out:{OutputOf(name)}",
            "-define:" + string.Join(";", Defines),
        };
        if (warningsAsErrors) args.Add("-warnaserror+");
        if (allowUnsafe) args.Add("-unsafe");
        args.AddRange(_frameworkReferences.Select(r => $"-r:{r}"));
        args.AddRange(references.Select(r => $"-r:{r}"));
        args.AddRange(sources);
        // Unity hands the csc.rsp's options to the compiler after its own.
        if (responseFile != null) args.AddRange(ReadResponseFile(responseFile));

        string rsp = Path.Combine(_outputFolder, name + ".args.rsp");
        File.WriteAllLines(rsp, args.Select(Quote));
        var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add("exec");
        start.ArgumentList.Add(_csc);
        // Not the csc.rsp beside csc.dll (the SDK's default references): Unity gives its own.
        start.ArgumentList.Add("-noconfig");
        start.ArgumentList.Add("@" + rsp);
        using Process process = Process.Start(start) ?? throw new InvalidOperationException("could not start csc");
        var stderr = process.StandardError.ReadToEndAsync();
        string output = process.StandardOutput.ReadToEnd() + stderr.Result;
        process.WaitForExit();
        return (process.ExitCode == 0, output.Trim());
    }

    /// <summary>The options of a csc.rsp, one or more per line, '#' lines being comments (as csc reads it).</summary>
    public static IEnumerable<string> ReadResponseFile(string path) =>
        File.ReadAllLines(path).Select(l => l.Trim()).Where(l => l.Length > 0 && !l.StartsWith("#", StringComparison.Ordinal))
            .SelectMany(l => l.Split(' ', StringSplitOptions.RemoveEmptyEntries));

    static string Quote(string arg) => arg.Contains(' ') ? "\"" + arg + "\"" : arg;
}
