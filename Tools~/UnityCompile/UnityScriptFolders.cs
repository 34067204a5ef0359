using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace Fulcrum.UnityCompile;

/// <summary>
/// Which scripts Unity sees and which assembly each goes to. Unity skips hidden entries (a
/// name starting with '.'), names ending in '~', "cvs" and "*.tmp"; a script belongs to the
/// .asmdef of the nearest folder at or above it that has one.
/// </summary>
static class UnityScriptFolders
{
    public static bool HiddenFromUnity(string name) =>
        name.StartsWith(".", StringComparison.Ordinal) || name.EndsWith("~", StringComparison.Ordinal) ||
        name.Equals("cvs", StringComparison.OrdinalIgnoreCase) || name.EndsWith(".tmp", StringComparison.OrdinalIgnoreCase);

    /// <summary>
    /// The assemblies under <paramref name="root"/> as Unity would import it. Scripts outside
    /// any asmdef would go to Assembly-CSharp: they are returned in <paramref name="orphans"/>.
    /// </summary>
    public static List<AsmdefAssembly> Discover(string root, List<string> orphans)
    {
        var found = new List<AsmdefAssembly>();
        Walk(root, owner: null, found, orphans);
        return found;
    }

    static void Walk(string folder, AsmdefAssembly? owner, List<AsmdefAssembly> found, List<string> orphans)
    {
        string[] asmdefs = Directory.GetFiles(folder, "*.asmdef");
        if (asmdefs.Length > 1) throw new InvalidDataException($"{folder}: {asmdefs.Length} .asmdef files in one folder (Unity allows one)");
        if (asmdefs.Length == 1)
        {
            owner = AsmdefAssembly.Read(asmdefs[0]);
            found.Add(owner);
        }
        foreach (string file in Directory.GetFiles(folder, "*.cs").OrderBy(f => f, StringComparer.Ordinal))
        {
            if (HiddenFromUnity(Path.GetFileName(file))) continue;
            if (owner != null) owner.Sources.Add(file);
            else orphans.Add(file);
        }
        foreach (string sub in Directory.GetDirectories(folder).OrderBy(f => f, StringComparer.Ordinal))
            if (!HiddenFromUnity(Path.GetFileName(sub))) Walk(sub, owner, found, orphans);
    }
}
