using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class PinnedFlagTests
    {
        // pinned-flag.json: the format's soft mesh is a box only, so the "flag" is a thin tet box
        // 1 x 0.02 x 0.6 m (cells 10, 1, 6; E = 1e5 Pa, 200 kg/m^3) laid flat at y = 2 m and pinned
        // along one edge (the top row of the x = -0.5 face, a hinge line), released to swing down.
        const float Length = 1f, PinY = 2.01f, PinX = -0.5f;

        [Test]
        public void Flag_pinned_along_one_edge_swings_down_without_stretching_or_gaining_energy()
        {
            SoftSceneRun run = SoftSceneRun.Load("pinned-flag");
            float g = 9.81f, mass = run.Body.TotalMass, startY = run.Body.ComputeStats().Centroid.Y;
            int steps = run.StepsIn(3f);
            float deepest = 0f, longest = 0f, worstExcess = float.MinValue, minJ = 1f, worstAt = 0f;
            SoftBodyStats worst = default;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                SoftBodyStats s = run.Body.ComputeStats();
                minJ = MathF.Min(minJ, s.MinJ);
                float excess = SoftSceneRun.Energy(s) - mass * g * (startY - s.Centroid.Y);
                if (excess > worstExcess) { worstExcess = excess; worstAt = (n + 1) * run.Timestep; worst = s; }
                Vector3 edge = run.Body.GetProbe(0);
                deepest = MathF.Max(deepest, PinY - edge.Y);
                longest = MathF.Max(longest, new Vector2(edge.X - PinX, edge.Y - PinY).Length());
            }
            TestContext.Out.WriteLine($"pinned-flag: free edge fell to {deepest:F3} m below the pin line; longest pin-to-edge distance {longest:F4} m (rest {Length}); min J {minJ:F3}; energy excess over gravity's work {worstExcess:F3} J of {mass * g * 0.5f:F1} J available (at {worstAt:F2} s: kinetic {worst.KineticEnergy:F2} J, strain {worst.StrainEnergy:F2} J, gravity work {mass * g * (startY - worst.Centroid.Y):F2} J)");

            Assert.That(run.AllFinite(), Is.True);
            Assert.That(deepest, Is.GreaterThan(0.8f * Length), "the flag swings down from its edge");
            // A rod pendulum released level pulls 2.5 m g at its pivot at the bottom of the swing:
            // about 5 % strain at the root for E = 1e5 Pa; the hinge-line pin concentrates more.
            Assert.That(longest, Is.LessThan(1.10f * Length), "and does not stretch more than 10 %");
            // Strain + kinetic energy should stay within the work gravity did; the thin one-layer
            // tet sheet overshoots it by about a third (known, reported), a blow-up by far more.
            Assert.That(worstExcess, Is.LessThan(0.5f * mass * g * 0.5f), "no energy blow-up");
            Assert.That(minJ, Is.GreaterThan(0.5f));
        }
    }
}
