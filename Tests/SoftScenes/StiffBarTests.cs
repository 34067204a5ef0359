using System;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class StiffBarTests
    {
        // stiff-bar.json: a 1 m x 0.1 m x 0.1 m bar, E = 1e9 Pa, 1000 kg/m^3, clamped at x = -0.5 by a pin box, 60 Hz.
        const float Length = 1f, Side = 0.1f, E = 1e9f, Density = 1000f;

        [Test]
        public void Stiff_cantilever_at_60Hz_stays_finite_and_bounded()
        {
            SoftSceneRun run = SoftSceneRun.Load("stiff-bar");
            float restTip = run.Body.GetProbe(0).Y;
            int steps = run.StepsIn(4f);
            float firstHalfMax = 0f, secondHalfMax = 0f, lowestTip = float.MaxValue, tipSum = 0f, minJ = 1f;
            int tipCount = 0;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                SoftBodyStats s = run.Body.ComputeStats();
                float energy = SoftSceneRun.Energy(s);
                if (n < steps / 2) firstHalfMax = MathF.Max(firstHalfMax, energy);
                else secondHalfMax = MathF.Max(secondHalfMax, energy);
                float tip = run.Body.GetProbe(0).Y;
                lowestTip = MathF.Min(lowestTip, tip);
                minJ = MathF.Min(minJ, s.MinJ);
                if (n >= steps / 2) { tipSum += tip; tipCount++; }
            }
            float meanSag = restTip - tipSum / tipCount;
            // Euler-Bernoulli: w = q L^4 / (8 E I), q = rho g A, I = a^4 / 12.
            float q = Density * 9.81f * Side * Side, inertia = Side * Side * Side * Side / 12f;
            float beamSag = q * Length * Length * Length * Length / (8f * E * inertia);
            TestContext.Out.WriteLine($"stiff-bar: mean tip sag over the last 2 s {meanSag:F4} m (largest {restTip - lowestTip:F4} m) vs Euler-Bernoulli {beamSag:E2} m ({meanSag / beamSag:F0}x softer)");
            double reference = ReferenceSag(run.Body);
            TestContext.Out.WriteLine($"stiff-bar: converged sag on this mesh (Newton static equilibrium) {reference * 1e3:F3} mm; XPBD sags {meanSag / reference:F0}x that");
            TestContext.Out.WriteLine($"stiff-bar: max strain+kinetic energy first 2 s {firstHalfMax:F0} J, last 2 s {secondHalfMax:F0} J; min J {minJ:F3}");

            Assert.That(run.AllFinite(), Is.True);
            Assert.That(secondHalfMax, Is.LessThanOrEqualTo(1.1f * firstHalfMax), "energy does not grow");
            Assert.That(restTip - lowestTip, Is.LessThan(Length), "the tip cannot hang further than the bar is long");
            Assert.That(meanSag, Is.GreaterThan(0f));
            Assert.That(minJ, Is.GreaterThan(0f));
            Assert.That(reference, Is.GreaterThan(0.0).And.LessThan(beamSag), "the converged linear-tet bar is stiffer than the beam (locking)");
        }

        /// <summary>Mean tip-face sag of the body's own mesh at static equilibrium, its pinned vertices held.</summary>
        static double ReferenceSag(SoftBody body)
        {
            var eq = new StaticEquilibrium(body.Mesh, body.Material);
            ReadOnlySpan<System.Numerics.Vector3> rest = body.Mesh.Vertices;
            for (int i = 0; i < rest.Length; i++) if (body.InverseMasses[i] == 0f) eq.Pin(i);
            eq.AddGravity(new System.Numerics.Vector3(0f, -9.81f, 0f));
            Assert.That(eq.Solve(), Is.True, $"reference residual {eq.Residual} N");
            double sag = 0;
            int tip = 0;
            for (int i = 0; i < rest.Length; i++)
                if (rest[i].X > 0.5f * Length - 1e-4f) { sag += rest[i].Y - eq.Position(i).Y; tip++; }
            return sag / tip;
        }
    }
}
