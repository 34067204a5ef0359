using System;
using System.IO;
using System.Numerics;
using Fulcrum.Runner;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.RigidScenes;
using NUnit.Framework;

namespace Fulcrum.Tests.State
{
    // The tests of StateRoundTripTests that need the runner (Samples~/Runner) or .NET-only APIs: net10 only
    // (this folder ends in '~', so Unity never compiles it); the rest is in Tests/.
    public partial class StateRoundTripTests
    {
        [Test]
        public void Fuzzed_worlds_of_every_shape_and_joint_kind_continue_bit_identically_in_a_fresh_world()
        {
            int compared = 0;
            for (int seed = 0; seed < 60; seed++)
            {
                World? a = WorldFuzz.Build(seed, out _, out _);
                if (a == null) continue;
                for (int n = 0; n < 30; n++) a.Step(1 / 60f);
                byte[] state = Save(a);
                for (int n = 0; n < 30; n++) a.Step(1 / 60f);

                var b = new World();
                Restore(b, state);
                for (int n = 0; n < 30; n++) b.Step(1 / 60f);
                Assert.That(Save(b), Is.EqualTo(Save(a)), $"seed {seed} ({a.Settings.Solver}, {a.Settings.Threads} threads)");
                compared++;
            }
            Assert.That(compared, Is.GreaterThan(40));
        }
    }
}
