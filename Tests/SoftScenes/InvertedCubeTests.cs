using System;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class InvertedCubeTests
    {
        // inverted-cube.json: a 0.5 m stable Neo-Hookean cube (E = 5e4 Pa, nu = 0.45) started
        // through itself: initialDeformation [[1, 0.1, 0], [0, -0.6, 0], [0, 0, 1]], det = -0.6.
        [Test]
        public void Cube_started_inverted_recovers_its_orientation_and_volume()
        {
            SoftSceneRun run = SoftSceneRun.Load("inverted-cube");
            SoftBodyStats start = run.Body.ComputeStats();
            int steps = run.StepsIn(3f);
            float recoveredAt = float.NaN;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                if (float.IsNaN(recoveredAt) && run.Body.ComputeStats().MinJ > 0f) recoveredAt = (n + 1) * run.Timestep;
            }
            SoftBodyStats end = run.Body.ComputeStats();
            TestContext.Out.WriteLine($"inverted-cube: start volume ratio {start.VolumeRatio:F3}, min J {start.MinJ:F3}; every element positive after {recoveredAt:F3} s; end volume ratio {end.VolumeRatio:F4}, min J {end.MinJ:F3}");

            Assert.That(start.VolumeRatio, Is.EqualTo(-0.6f).Within(1e-3f), "starts inverted");
            Assert.That(run.AllFinite(), Is.True);
            Assert.That(end.MinJ, Is.GreaterThan(0.5f));
            Assert.That(end.VolumeRatio, Is.EqualTo(1f).Within(0.02f));
        }
    }
}
