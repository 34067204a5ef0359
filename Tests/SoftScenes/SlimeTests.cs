using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class SlimeTests
    {
        // slime.json: a 0.3 m cube of E = 1e3 Pa, nu = 0.495 set on the ground, elastic;
        // rho g h / E = 2.9, so it slumps. slime-plastic.json adds plasticity.
        const float Size = 0.3f;

        static float Height(SoftSceneRun run) => run.Body.GetProbe(0).Y - run.Body.GetProbe(1).Y;

        [Test]
        public void Elastic_slime_on_the_ground_flattens_and_keeps_its_volume()
        {
            SoftSceneRun run = SoftSceneRun.Load("slime");
            float g = 9.81f, mass = run.Body.TotalMass, startY = run.Body.ComputeStats().Centroid.Y;
            int steps = run.StepsIn(3f), tail = run.StepsIn(0.5f);
            float heightSum = 0f, worstExcess = float.MinValue, minJ = 1f;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                SoftBodyStats s = run.Body.ComputeStats();
                minJ = MathF.Min(minJ, s.MinJ);
                worstExcess = MathF.Max(worstExcess, SoftSceneRun.Energy(s) - mass * g * (startY - s.Centroid.Y));
                if (n >= steps - tail) heightSum += Height(run);
            }
            SoftBodyStats end = run.Body.ComputeStats();
            float height = heightSum / tail;
            TestContext.Out.WriteLine($"slime: height {height:F4} m of {Size} m ({height / Size:P0}), volume error {MathF.Abs(end.VolumeRatio - 1f):P2}, min J over the run {minJ:F3}, energy excess over gravity's work {worstExcess:F3} J");

            Assert.That(run.AllFinite(), Is.True);
            Assert.That(height, Is.LessThan(0.6f * Size), "flattens");
            Assert.That(height, Is.GreaterThan(0.1f * Size), "but does not collapse");
            Assert.That(end.VolumeRatio, Is.EqualTo(1f).Within(0.03f));
            Assert.That(minJ, Is.GreaterThan(0f));
            Assert.That(worstExcess, Is.LessThan(0.01f * mass * g * startY));
        }

        static float TopToBottom(SoftSceneRun run) => Vector3.Distance(run.Body.GetProbe(0), run.Body.GetProbe(1));

        // Top-to-bottom distance after slumping for 2 s and then 2 s with gravity off: an elastic
        // body springs back (and hops off the ground, tumbling, so the distance and not the
        // height is measured), a plastic one keeps its slump.
        static float HeightAfterUnloading(string file, out float loaded, out float volume)
        {
            SoftSceneRun run = SoftSceneRun.Load(file);
            for (int n = 0; n < run.StepsIn(2f); n++) run.Step();
            loaded = Height(run);
            run.Body.GravityScale = 0f;
            int steps = run.StepsIn(2f), tail = run.StepsIn(0.5f);
            float sum = 0f;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                if (n >= steps - tail) sum += TopToBottom(run);
            }
            Assert.That(run.AllFinite(), Is.True);
            volume = run.Body.ComputeStats().VolumeRatio;
            return sum / tail;
        }

        [Test]
        public void Plastic_slime_keeps_its_slump_when_gravity_is_switched_off()
        {
            // slime-plastic.json is slime.json plus "plasticity": { "yieldStrain": 0.05, "flowRate": 5 }.
            float elastic = HeightAfterUnloading("slime", out float elasticLoaded, out float elasticVolume);
            float plastic = HeightAfterUnloading("slime-plastic", out float plasticLoaded, out float plasticVolume);
            TestContext.Out.WriteLine($"slime unloading (height under gravity -> top-to-bottom distance 2 s after gravity is off): elastic {elasticLoaded:F4} m -> {elastic:F4} m, plastic (yield 0.05, 5/s) {plasticLoaded:F4} m -> {plastic:F4} m, of {Size} m; volume ratios {elasticVolume:F4}, {plasticVolume:F4}");

            Assert.That(elastic, Is.EqualTo(Size).Within(0.15f * Size), "elastic slime springs back to its rest height");
            Assert.That(plastic, Is.LessThan(elastic - 0.2f * Size), "plastic slime keeps most of its slump");
            Assert.That(plasticVolume, Is.EqualTo(1f).Within(0.03f), "plastic flow is volume preserving");
        }
    }
}
