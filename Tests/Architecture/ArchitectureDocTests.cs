using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace Fulcrum.Tests.Architecture
{
    /// <summary>
    /// Keeps Documentation~/Architecture.md true to the code: its stage table names exactly the
    /// <see cref="StepStage"/> values in order, and each stage has its World.&lt;Stage&gt;.cs
    /// file holding a World method of the same name.
    /// </summary>
    public class ArchitectureDocTests
    {
        static string Root()
        {
            for (var d = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); d != null; d = d.Parent)
                if (File.Exists(Path.Combine(d.FullName, "package.json"))) return d.FullName;
            throw new AssertionException("package.json not found above the test directory");
        }

        static readonly string[] Stages = Enum.GetNames(typeof(StepStage));

        [Test]
        public void Stage_table_names_the_StepStage_values_in_order()
        {
            string doc = File.ReadAllText(Path.Combine(Root(), "Documentation~", "Architecture.md"));
            // Rows of the step table: "| 3 | Solve | World.Solve.cs | ...".
            var rows = Regex.Matches(doc, @"^\| (\d+) \| (\w+) \| (World\.\w+\.cs)", RegexOptions.Multiline)
                .Cast<Match>().ToList();
            Assert.That(rows.Select(m => m.Groups[2].Value).ToArray(), Is.EqualTo(Stages));
            Assert.That(rows.Select(m => int.Parse(m.Groups[1].Value)).ToArray(),
                Is.EqualTo(Stages.Select(s => (int)Enum.Parse(typeof(StepStage), s)).ToArray()));
            Assert.That(rows.Select(m => m.Groups[3].Value).ToArray(), Is.EqualTo(Stages.Select(s => "World." + s + ".cs").ToArray()));
            // The reads/writes table lists the same stages in the same order.
            var io = Regex.Matches(doc, @"^\| (\w+) \| [^|]+ \| [^|]+ \|$", RegexOptions.Multiline)
                .Cast<Match>().Select(m => m.Groups[1].Value).Where(s => Stages.Contains(s)).ToArray();
            Assert.That(io, Is.EqualTo(Stages));
        }

        [Test]
        public void Each_stage_has_its_file_and_method()
        {
            string dir = Path.Combine(Root(), "Runtime", "Core", "World");
            var missing = new List<string>();
            foreach (string stage in Stages)
            {
                string file = Path.Combine(dir, "World." + stage + ".cs");
                if (!File.Exists(file)) { missing.Add(file); continue; }
                if (!Regex.IsMatch(File.ReadAllText(file), @"\bvoid " + stage + @"\(")) missing.Add(stage + " method in " + file);
                MethodInfo? m = typeof(World).GetMethod(stage, BindingFlags.Instance | BindingFlags.NonPublic);
                if (m == null) missing.Add("World." + stage + "()");
            }
            Assert.That(missing, Is.Empty);
        }
    }
}
