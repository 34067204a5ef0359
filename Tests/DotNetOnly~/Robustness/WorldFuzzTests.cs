using System.Collections.Generic;
using Fulcrum.Runner;
using NUnit.Framework;

namespace Fulcrum.Tests.Robustness
{
    /// <summary>
    /// The fuzz suite CI runs: seeded hostile worlds (WorldFuzz) that must either be refused by
    /// the API with an ArgumentException or run without diverging (no NaN, nothing past the
    /// world bounds: World.Diverged never fires). The failing seeds are listed one per line so
    /// each can be replayed on its own.
    /// <para>
    /// Known and not yet fixed: in 1 of seeds 0-19999 (14973, PGS; `fulcrum fuzz`) the
    /// mechanical energy still rises above what motors and corrections may add, by 3.7 %. The
    /// counts here are measured and held as ceilings, so they can only go down.
    /// </para>
    /// </summary>
    public class WorldFuzzTests
    {
        // Measured on seeds 0-299 (180 steps each): 0 refused, 0 diverged, 0 escaped, 0 gained
        // energy. Seed 67 (a 14 g body at 300 rad/s) gained energy until TGS refreshed the world
        // inverse inertia each substep; seed 69 (joints created 2.4 m violated that cannot all
        // be met, lifting a 1.6 t body 12 m) until the correction cap's stiffening was limited
        // to 8 times; and most others until the free-rotation splitting took fast turns in
        // parts of 0.1 rad (seed 887: a capsule spun from 131 to 866 rad/s in one step). Before the energy
        // guard (Dynamics/EnergyGuard), the angular velocity turned with PGS's position passes,
        // the capped joint position passes, the warm start dropped for runaway joint impulses and
        // the reach that lets a light body carry the world's kinetic energy: 3 escaped and 25
        // gained energy here (30 and 115 of seeds 0-1999).
        //
        // Energy (WorldFuzz.Outcome.EnergyGain): kinetic, rotational and potential energy may not
        // rise above what the motors (max torque x target speed x time), the correction passes
        // (every body at MaxJointCorrectionSpeed + MaxContactPushSpeed) and the lift of every
        // body by the largest joint error at creation may add.
        [TestCase(0, 150, 0, 0)]
        [TestCase(150, 150, 0, 0)]
        public void Hostile_worlds_are_refused_or_never_diverge(int firstSeed, int count, int escapesMeasured, int energyGainsMeasured)
        {
            var failures = new List<string>();
            var escapes = new List<string>();
            var gains = new List<string>();
            int refused = 0;
            for (int seed = firstSeed; seed < firstSeed + count; seed++)
            {
                WorldFuzz.Outcome o = WorldFuzz.Run(seed, 180);
                if (o.Refused) refused++;
                if (o.Failure != null) failures.Add(o.Failure);
                if (o.Escape != null) escapes.Add(o.Escape);
                if (o.EnergyGain != null) gains.Add(o.EnergyGain);
            }
            TestContext.Out.WriteLine($"{count} worlds: {refused} refused, {failures.Count} diverged, {escapes.Count} escaped, {gains.Count} gained energy");
            foreach (string f in failures) TestContext.Out.WriteLine("diverged: " + f);
            foreach (string e in escapes) TestContext.Out.WriteLine("escaped: " + e);
            foreach (string g in gains) TestContext.Out.WriteLine("energy: " + g);
            Assert.That(failures, Is.Empty);
            Assert.That(escapes.Count, Is.LessThanOrEqualTo(escapesMeasured));
            Assert.That(gains.Count, Is.LessThanOrEqualTo(energyGainsMeasured));
        }

        // The worlds that showed each mechanism, replayed: 66 (PGS: a thin body turned by joint
        // corrections kept its world angular velocity, so its rotational energy rose with the
        // turned inertia; 14 kJ -> 5.6 MJ), 119 (TGS: a 2 t body between two world ball joints
        // that disagree spun up to 1.2 MJ), 229 (PGS: 0.06-0.09 kg links holding 633 kg; the
        // warm-started impulses of redundant rows drifted, 14 kJ -> 860 kJ and a link flung past
        // its reach), 1498 (PGS: the same drift overflowed to infinity, then NaN, in step 83 once
        // the position passes were capped), 69 (TGS 1x8, no relax: unsatisfiable joints created
        // 2.4 m violated lifted a 1.6 t body 12 m while the correction cap stiffened rows without
        // limit), 887 (PGS: a 621 kg capsule turning 2 rad per step spun to 866 rad/s in the
        // free-rotation splitting), 1547 (TGS, one substep: the relax passes, working on the
        // step's start contact geometry, spun a compound turning 1.9 rad per step from 113 to 483
        // rad/s in a contact-only island), 10447 (TGS 2x1: a limited hinge and a ball joint
        // holding a 9.9 t capsule to world points they cannot both meet; warm started up to the
        // old runaway bound, their cancelling impulses grew to 8e6 N s, lifted it 6 m and threw
        // it 19 m from its anchors: 21 % over the allowance; the joints now start cold beyond
        // JointSolver.MaxWarmImpulse).
        [TestCase(66)]
        [TestCase(69)]
        [TestCase(10447)]
        [TestCase(887)]
        [TestCase(1547)]
        [TestCase(119)]
        [TestCase(229)]
        [TestCase(1498)]
        public void Worlds_that_pumped_energy_through_contradictory_joints_now_keep_it(int seed)
        {
            KeepsItsEnergy(seed);
        }

        // TGS turns the bodies inside the energy guard's window, and a free body keeps its
        // angular momentum, not its world angular velocity. The guard used to scale a turned
        // body back toward its start angular velocity in its turned pose, which moved energy
        // onto its heavy axes: 1388 (a 2.7 t rod spinning at the speed cap about its long axis,
        // 2.3 to 16 MJ in three steps) and, before the fix, 12 more of seeds 0-19999 gained
        // energy this way (2008, 5143, 10078, 10539, 11177 and 11701 up to 17 MJ, the others
        // within 5 % of their allowance). Now the start velocity is carried as momentum and a
        // turned island's rotation ends no higher than it began (EnergyGuard remarks).
        [TestCase(1388)]
        [TestCase(2008)]
        [TestCase(5143)]
        [TestCase(10078)]
        [TestCase(10539)]
        [TestCase(11177)]
        [TestCase(11701)]
        [TestCase(928)]
        public void Worlds_with_bodies_turning_under_the_energy_guard_keep_their_energy(int seed)
        {
            KeepsItsEnergy(seed);
        }

        // The shock-propagation sweep holds a dynamic lower body still as a support only: once
        // it was speculative (acting on contacts a step's approach would close), a 0.35 kg body
        // flying at 88 m/s into an 8 t one in zero gravity handed it its speed through the sweep
        // (4299: 1.3e7 J in the first step; 18913 under PGS, 9.7 kJ). The sweep now carries an
        // upper body along with a dynamic lower one at no more than MaxContactPushSpeed.
        [TestCase(4299)]
        [TestCase(18913)]
        public void Worlds_where_a_fast_light_body_strikes_a_heavy_one_keep_their_energy(int seed)
        {
            KeepsItsEnergy(seed);
        }

        // Replays world seed: it may not diverge, escape or gain energy.
        static void KeepsItsEnergy(int seed)
        {
            WorldFuzz.Outcome o = WorldFuzz.Run(seed, 180);
            TestContext.Out.WriteLine($"seed {seed}: energy rose at most {o.MaxEnergyRise:G3} J, allowance {o.EnergyAllowance:G3} J");
            Assert.That(o.Failure, Is.Null);
            Assert.That(o.Escape, Is.Null);
            Assert.That(o.EnergyGain, Is.Null);
        }

        [Test]
        public void The_fuzz_command_lists_failing_worlds_and_exits_3_only_when_one_failed()
        {
            var output = new System.IO.StringWriter();
            var error = new System.IO.StringWriter();
            int code = Cli.Run(new[] { "fuzz", "--count", "30", "--seed", "0", "--steps", "120" }, output, error);
            string[] lines = output.ToString().Split('\n', System.StringSplitOptions.RemoveEmptyEntries);
            TestContext.Out.WriteLine(output.ToString());
            string last = lines[lines.Length - 1].Trim();
            Assert.That(last, Does.StartWith("fuzz: 30 worlds from seed 0, 120 steps each: "));
            int listed = lines.Length - 1;
            Assert.That(code, Is.EqualTo(listed > 0 ? Cli.ExitDiverged : Cli.ExitOk));
            foreach (string line in lines[..^1]) Assert.That(line, Does.StartWith("escaped: seed ").Or.StartWith("diverged: seed ").Or.StartWith("energy: seed "));
            Assert.That(error.ToString(), Is.Empty);
        }
    }
}
