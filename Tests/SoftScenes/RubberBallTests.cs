using System;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class RubberBallTests
    {
        // rubber-ball-sphere.json: a rubber ball of radius 0.2 m (sphere mesh, 8 cells across;
        // E = 1e6 Pa, nu = 0.49, 1100 kg/m^3) dropped with its bottom 1 m above the ground.
        const float Radius = 0.2f, Drop = 1f;

        [TestCase(6)]
        [TestCase(8)]
        [TestCase(10)]
        public void Rubber_ball_dropped_from_1m_bounces_and_stays_round(int cells)
        {
            SoftSceneRun run = SoftSceneRun.Load("rubber-ball-sphere", d => ((SceneSoftSphere)d.SoftBodies[0].Mesh!).Cells = cells);
            SoftBody ball = run.Body;
            float g = 9.81f, mass = ball.TotalMass, startY = ball.ComputeStats().Centroid.Y;
            bool touched = false, left = false;
            SoftBodyStats end = default;
            float apex = float.MinValue, worstVolume = 0f, worstExcess = float.MinValue, minJ = 1f;
            int steps = run.StepsIn(2f);
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                SoftBodyStats s = ball.ComputeStats();
                minJ = MathF.Min(minJ, s.MinJ);
                worstVolume = MathF.Max(worstVolume, MathF.Abs(s.VolumeRatio - 1f));
                worstExcess = MathF.Max(worstExcess, SoftSceneRun.Energy(s) - mass * g * (startY - s.Centroid.Y));
                float bottom = ball.GetProbe(1).Y;
                if (!touched) { touched = bottom < 0.01f; continue; }
                // The first flight after the impact: from leaving the ground to coming back.
                if (!left) { left = s.Momentum.Y > 0 && bottom > 0.02f; if (!left) continue; }
                if (s.Momentum.Y < 0 && s.Centroid.Y < apex) break;
                if (s.Centroid.Y > apex) { apex = s.Centroid.Y; end = s; }
            }
            float rebound = apex - Radius;
            float restitution = MathF.Sqrt(MathF.Max(0f, rebound) / Drop);
            TestContext.Out.WriteLine($"rubber-ball-sphere, {cells} cells: rebound apex {rebound:F4} m of a {Drop} m drop ({rebound / Drop:P1}; restitution sqrt(h'/h) = {restitution:F3}); worst volume error {worstVolume:P2}; min J {minJ:F3}; strain + kinetic above gravity's work by at most {worstExcess:F3} J of {mass * g * Drop:F1} J");

            TestContext.Out.WriteLine($"rubber-ball-sphere: at the apex: volume ratio {end.VolumeRatio:F4}, min J {end.MinJ:F3}");

            Assert.That(run.AllFinite(), Is.True);
            Assert.That(left, Is.True, "the ball leaves the ground after the impact");
            // Real rubber returns 50-80 % of the height; at the default 0.01 s damping time the
            // ball returns 32-43 % (6-10 cells). Below 20 % the damping or the contact is eating
            // the bounce (the in-solve damping of 0.1.0 gave the block e = 0.22, i.e. 5 %).
            Assert.That(rebound, Is.GreaterThan(0.2f * Drop), "rebounds more than 20 % of the drop");
            Assert.That(rebound, Is.LessThan(Drop), "never higher than it fell");
            // With sliver-free carved meshes no element inverts at the 4.4 m/s impact (min J
            // 0.92 / 0.85 / 0.55 at 6 / 8 / 10 cells; the slivered meshes reached -0.52 at 8 and
            // -1.37 at 10). Reported, not asserted: strain + kinetic energy still rises above
            // gravity's work during the impact (-0.05 / 17 / 359 J at 6 / 8 / 10 cells, was
            // 41 / 541 / 2720 J) where the contact projection pushes the bottom layer up.
            Assert.That(minJ, Is.GreaterThan(0.3f), "no element inverts or is crushed during the impact");
            Assert.That(worstVolume, Is.LessThan(0.15f), "volume within 15 % even through the impact");
            Assert.That(end.VolumeRatio, Is.EqualTo(1f).Within(0.01f), "round again in flight: volume within 1 %");
            Assert.That(end.MinJ, Is.GreaterThan(0.9f), "no element left inverted or crushed");
        }
    }
}
