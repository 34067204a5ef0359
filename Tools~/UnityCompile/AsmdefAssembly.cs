using System;
using System.Collections.Generic;
using System.IO;
using System.Text.Json;

namespace Fulcrum.UnityCompile;

/// <summary>One .asmdef file: the assembly Unity builds from the scripts of its folder.</summary>
sealed class AsmdefAssembly
{
    public required string Name { get; init; }
    public required string AsmdefPath { get; init; }
    public required string Folder { get; init; }
    /// <summary>The asmdef's GUID (from its .meta file), for "GUID:..." references; null without a .meta (samples).</summary>
    public string? Guid { get; init; }
    public required IReadOnlyList<string> References { get; init; }
    public required IReadOnlyList<string> PrecompiledReferences { get; init; }
    public required IReadOnlyList<string> DefineConstraints { get; init; }
    public bool NoEngineReferences { get; init; }
    public bool OverrideReferences { get; init; }
    public bool AllowUnsafeCode { get; init; }
    /// <summary>The .cs files Unity compiles into this assembly (filled by <see cref="UnityScriptFolders"/>).</summary>
    public List<string> Sources { get; } = new();

    /// <summary>The folder's csc.rsp (Unity 2020.2+ passes it to the compiler for this assembly only), or null.</summary>
    public string? ResponseFile => File.Exists(Path.Combine(Folder, "csc.rsp")) ? Path.Combine(Folder, "csc.rsp") : null;

    public static AsmdefAssembly Read(string path)
    {
        using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(path), new JsonDocumentOptions { AllowTrailingCommas = true, CommentHandling = JsonCommentHandling.Skip });
        JsonElement root = doc.RootElement;
        string? guid = null;
        string meta = path + ".meta";
        if (File.Exists(meta))
            foreach (string line in File.ReadLines(meta))
                if (line.StartsWith("guid:", StringComparison.Ordinal)) guid = line.Substring(5).Trim();
        return new AsmdefAssembly
        {
            Name = root.GetProperty("name").GetString() ?? throw new InvalidDataException($"{path}: no name"),
            AsmdefPath = path,
            Folder = Path.GetDirectoryName(path)!,
            Guid = guid,
            References = Strings(root, "references"),
            PrecompiledReferences = Strings(root, "precompiledReferences"),
            DefineConstraints = Strings(root, "defineConstraints"),
            NoEngineReferences = Bool(root, "noEngineReferences"),
            OverrideReferences = Bool(root, "overrideReferences"),
            AllowUnsafeCode = Bool(root, "allowUnsafeCode"),
        };
    }

    static IReadOnlyList<string> Strings(JsonElement root, string property)
    {
        var list = new List<string>();
        if (root.TryGetProperty(property, out JsonElement array))
            foreach (JsonElement e in array.EnumerateArray()) list.Add(e.GetString() ?? "");
        return list;
    }

    static bool Bool(JsonElement root, string property) => root.TryGetProperty(property, out JsonElement e) && e.GetBoolean();
}
