using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class StretchedBlockTests
    {
        // stretched-block.json: a 0.6 x 0.2 x 0.2 m block (E = 1e5 Pa, nu = 0.45) in zero gravity,
        // started stretched to 3x its length (initialDeformation diag(3, 1, 1)) and released.
        const float RestLength = 0.6f;

        static float Length(SoftSceneRun run) => Vector3.Distance(run.Body.GetProbe(0), run.Body.GetProbe(1));

        static Vector3 AngularMomentum(SoftBody body, Vector3 about)
        {
            Vector3 l = Vector3.Zero;
            ReadOnlySpan<Vector3> x = body.Positions, v = body.Velocities;
            ReadOnlySpan<float> m = body.Masses;
            for (int i = 0; i < x.Length; i++) l += m[i] * Vector3.Cross(x[i] - about, v[i]);
            return l;
        }

        [Test]
        public void Block_stretched_3x_returns_to_its_rest_length_without_gaining_energy()
        {
            SoftSceneRun run = SoftSceneRun.Load("stretched-block");
            SoftBodyStats start = run.Body.ComputeStats();
            float startLength = Length(run);
            int steps = run.StepsIn(3f), tail = run.StepsIn(1f);
            float maxEnergy = 0f, lengthSum = 0f, maxLength = 0f;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                SoftBodyStats s = run.Body.ComputeStats();
                maxEnergy = MathF.Max(maxEnergy, SoftSceneRun.Energy(s));
                if (n >= steps - tail) { lengthSum += Length(run); maxLength = MathF.Max(maxLength, Length(run)); }
            }
            SoftBodyStats end = run.Body.ComputeStats();
            float length = lengthSum / tail;
            Vector3 spin = AngularMomentum(run.Body, end.Centroid);
            TestContext.Out.WriteLine($"stretched-block: length {startLength:F3} m -> mean {length:F4} m over the last second (rest {RestLength}), largest {maxLength:F4} m");
            TestContext.Out.WriteLine($"stretched-block: energy start {SoftSceneRun.Energy(start):F2} J, max after release {maxEnergy:F2} J, end {SoftSceneRun.Energy(end):F3} J; centroid drift {Vector3.Distance(end.Centroid, start.Centroid):E2} m; |momentum| {end.Momentum.Length():E2} kg m/s; |angular momentum| {spin.Length():E2} kg m^2/s; min J {end.MinJ:F3}");

            Assert.That(start.StrainEnergy, Is.GreaterThan(0f));
            Assert.That(run.AllFinite(), Is.True);
            Assert.That(length, Is.EqualTo(RestLength).Within(5).Percent);
            Assert.That(maxEnergy, Is.LessThanOrEqualTo(SoftSceneRun.Energy(start) * 1.001f), "no forces from outside: energy can only fall");
            Assert.That(Vector3.Distance(end.Centroid, start.Centroid), Is.LessThan(1e-3f), "momentum is conserved: the centroid stays put");
            Assert.That(end.MinJ, Is.GreaterThan(0.5f));
        }
    }
}
