using System;
using System.Collections;
using System.Collections.Generic;
using System.Reflection;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.RigidScenes;
using NUnit.Framework;

namespace Fulcrum.Tests.State
{
    // The tests of StateCoverageTests that need the runner (Samples~/Runner) or .NET-only APIs: net10 only
    // (this folder ends in '~', so Unity never compiles it); the rest is in Tests/.
    public partial class StateCoverageTests
    {
        [Test]
        public void Every_field_a_step_reads_is_restored_in_fuzzed_worlds()
        {
            var fields = new SortedSet<string>();
            for (int seed = 0; seed < 40; seed++)
            {
                World? a = Runner.WorldFuzz.Build(seed, out _, out _);
                if (a == null) continue;
                for (int n = 0; n < 40; n++) a.Step(1 / 60f);
                var b = new World();
                StateRoundTripTests.Restore(b, StateRoundTripTests.Save(a));
                var diffs = new List<string>();
                Compare(a, b, "World", diffs, new HashSet<object>(ReferenceComparer.Instance));
                foreach (string d in diffs) fields.Add($"seed {seed}: " + System.Text.RegularExpressions.Regex.Replace(d, @"\[\d+\]", "[]"));
            }
            Assert.That(fields, Is.Empty);
        }
    }
}
