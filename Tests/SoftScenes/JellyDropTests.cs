using System;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class JellyDropTests
    {
        // jelly-drop.json: a 0.5 m jelly cube (E = 2e4 Pa, nu = 0.48, 1000 kg/m^3) dropped 0.5 m onto the ground.
        const float Size = 0.5f, E = 2e4f, Density = 1000f, Radius = 0.005f;

        [Test]
        public void Jelly_cube_dropped_on_the_ground_wobbles_settles_to_its_self_weight_sag_and_keeps_its_volume()
        {
            SoftSceneRun run = SoftSceneRun.Load("jelly-drop");
            int steps = run.StepsIn(3f);
            float restHeight = Size;
            float minHeight = float.MaxValue, maxHeightAfterLow = float.MinValue, worstVolume = 0f;
            bool touched = false;
            var heights = new float[steps];
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                float height = run.Body.GetProbe(0).Y - run.Body.GetProbe(1).Y;
                heights[n] = height;
                if (run.Body.GetProbe(1).Y < 0.01f) touched = true;
                if (touched) worstVolume = MathF.Max(worstVolume, MathF.Abs(run.Body.ComputeStats().VolumeRatio - 1f));
            }
            Assert.That(run.AllFinite(), Is.True);
            SoftBodyStats end = run.Body.ComputeStats();
            float settled = heights[steps - 1];

            // Wobble: after the impact the height swings about its settled value; count the swings larger than 5 mm.
            int swings = 0, sign = 0;
            for (int n = 0; n < steps; n++)
            {
                float d = heights[n] - settled;
                if (MathF.Abs(d) < 0.005f) continue;
                int s = Math.Sign(d);
                if (sign != 0 && s != sign) swings++;
                sign = s;
                minHeight = MathF.Min(minHeight, heights[n]);
                if (minHeight < settled) maxHeightAfterLow = MathF.Max(maxHeightAfterLow, heights[n]);
            }

            // Settled: the top sits at the uniaxial self-weight sag rho g L^2 / (2E) below its rest
            // height (a column free to bulge; ground friction stiffens the bottom a little).
            float expectedSag = Density * 9.81f * restHeight * restHeight / (2f * E);
            float sag = (restHeight + Radius) - run.Body.GetProbe(0).Y;
            float meanSpeed = MathF.Sqrt(2f * end.KineticEnergy / run.Body.TotalMass);
            float dropEnergy = run.Body.TotalMass * 9.81f * 0.5f;
            // Uniaxial self-weight strain energy A (rho g)^2 L^3 / (6E), the figure a resting column holds.
            float expectedStrain = Size * Size * (Density * 9.81f) * (Density * 9.81f) * Size * Size * Size / (6f * E);
            TestContext.Out.WriteLine($"jelly-drop: swings {swings}, min height {minHeight:F4} m, rebound height {maxHeightAfterLow:F4} m, settled height {settled:F4} m");
            TestContext.Out.WriteLine($"jelly-drop: top sag {sag:F4} m vs rho g L^2/2E = {expectedSag:F4} m; volume error end {MathF.Abs(end.VolumeRatio - 1f):P2}, worst after impact {worstVolume:P2}; min J {end.MinJ:F3}; rms speed {meanSpeed:E2} m/s; strain {end.StrainEnergy:F2} J vs uniaxial {expectedStrain:F2} J; kinetic {end.KineticEnergy:E2} J of {dropEnergy:F0} J dropped");

            Assert.That(swings, Is.GreaterThanOrEqualTo(3), "the jelly should wobble visibly (height swings > 5 mm)");
            Assert.That(sag, Is.EqualTo(expectedSag).Within(15).Percent);
            Assert.That(end.VolumeRatio, Is.EqualTo(1f).Within(0.02f));
            Assert.That(worstVolume, Is.LessThan(0.05f));
            Assert.That(end.MinJ, Is.GreaterThan(0.9f));
            Assert.That(end.StrainEnergy, Is.EqualTo(expectedStrain).Within(35).Percent);
            Assert.That(end.KineticEnergy, Is.LessThan(1e-3f * dropEnergy), "settled: less than 0.1 % of the drop's energy left as motion");
        }
    }
}
