using System;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class RubberBlockTests
    {
        // rubber-ball.json: the block version of the rubber ball (rubber-ball-sphere.json is the sphere): a
        // 0.4 m rubber block (E = 1e6 Pa, nu = 0.49) dropped from 1 m (bottom face 1 m up).
        [Test]
        public void Rubber_block_dropped_from_1m_bounces_and_stays_within_its_energy()
        {
            SoftSceneRun run = SoftSceneRun.Load("rubber-ball");
            float g = 9.81f, mass = run.Body.TotalMass;
            float startY = run.Body.ComputeStats().Centroid.Y;
            float dropHeight = run.Body.GetProbe(1).Y;
            bool touched = false;
            float lowest = float.MaxValue, rebound = 0f, worstExcess = float.MinValue, minJ = 1f, maxRiseSpeed = 0f;
            int steps = run.StepsIn(2f);
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                SoftBodyStats s = run.Body.ComputeStats();
                float bottom = run.Body.GetProbe(1).Y;
                minJ = MathF.Min(minJ, s.MinJ);
                // Energy balance: strain + kinetic can never exceed the work gravity has done.
                worstExcess = MathF.Max(worstExcess, SoftSceneRun.Energy(s) - mass * g * (startY - s.Centroid.Y));
                if (!touched && bottom < 0.01f) touched = true;
                if (!touched) continue;
                lowest = MathF.Min(lowest, s.Centroid.Y);
                rebound = MathF.Max(rebound, s.Centroid.Y - lowest);
                maxRiseSpeed = MathF.Max(maxRiseSpeed, s.Momentum.Y / mass);
            }
            SoftBodyStats end = run.Body.ComputeStats();
            float impactSpeed = MathF.Sqrt(2f * g * dropHeight);
            TestContext.Out.WriteLine($"rubber-ball: impact speed {impactSpeed:F2} m/s, largest upward centroid speed after contact {maxRiseSpeed:F3} m/s (restitution ~{maxRiseSpeed / impactSpeed:F2}), centroid rebound {rebound:F4} m");
            TestContext.Out.WriteLine($"rubber-ball: min J {minJ:F3}, energy excess over gravity's work {worstExcess:F3} J of {mass * g * dropHeight:F0} J, end volume error {MathF.Abs(end.VolumeRatio - 1f):P2}");

            Assert.That(run.AllFinite(), Is.True);
            Assert.That(touched, Is.True);
            Assert.That(maxRiseSpeed, Is.GreaterThan(0.1f), "bounces: the centroid moves up after first contact");
            Assert.That(rebound, Is.GreaterThan(0.01f));
            Assert.That(maxRiseSpeed, Is.LessThan(impactSpeed), "a bounce cannot return more speed than the impact had");
            Assert.That(worstExcess, Is.LessThan(0.01f * mass * g * dropHeight));
            Assert.That(minJ, Is.GreaterThan(0.5f));
            Assert.That(end.VolumeRatio, Is.EqualTo(1f).Within(0.01f));
        }
    }
}
