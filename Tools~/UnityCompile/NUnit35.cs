using System;
using System.Collections.Generic;
using System.IO;

namespace Fulcrum.UnityCompile;

/// <summary>
/// The gap between the NUnit the tests compile against here (3.6.0, the oldest on the package
/// feed) and the one Unity's Test Framework ships (3.5): members NUnit 3.6 added, per its
/// release notes and documentation (Assert.Multiple; the Warn class and Assert.Warn). A test
/// that uses one would compile here and fail in Unity, so its text is refused.
/// </summary>
static class NUnit35
{
    static readonly string[] AddedIn36 = { "Assert.Multiple(", "Assert.Warn(", "Warn.If(", "Warn.Unless(" };

    /// <summary>"FILE(LINE): ..." for each use of a member newer than NUnit 3.5.</summary>
    public static IEnumerable<string> Check(IEnumerable<string> sources)
    {
        foreach (string file in sources)
        {
            int line = 0;
            foreach (string text in File.ReadLines(file))
            {
                line++;
                foreach (string member in AddedIn36)
                    if (text.Contains(member, StringComparison.Ordinal))
                        yield return $"{file}({line}): {member.TrimEnd('(')} is newer than NUnit 3.5 (Unity's Test Framework)";
            }
        }
    }
}
