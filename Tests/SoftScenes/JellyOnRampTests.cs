using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class JellyOnRampTests
    {
        // jelly-on-ramp.json: a 0.3 m jelly cube (E 5e4 Pa, nu 0.45, 4^3 cells, friction 0.1) set
        // 1 cm above a static convex-hull wedge sloping 25 degrees down towards +x (material
        // friction 0.1, so every combine mode gives mu = 0.1), and released. jelly-on-mesh-ramp.json
        // is the same with the wedge's slope face as a two-triangle static mesh.
        const float SlopeDeg = 25f, Mu = 0.1f, G = 9.81f;

        [TestCase("jelly-on-ramp")]
        [TestCase("jelly-on-mesh-ramp")]
        public void Jelly_slides_down_a_ramp_at_g_sin_minus_mu_cos_and_stays_on_its_surface(string scene)
        {
            SoftSceneRun run = SoftSceneRun.Load(scene);
            SoftBody jelly = run.Body;
            float theta = SlopeDeg * MathF.PI / 180f;
            var normal = new Vector3(MathF.Sin(theta), MathF.Cos(theta), 0);
            var down = new Vector3(MathF.Cos(theta), -MathF.Sin(theta), 0);
            float planeOffset = 1.5f * MathF.Sin(theta); // the face passes through the wedge's foot (1.5, 0, 0)
            int steps = run.StepsIn(0.9f);
            // Least-squares fit of s(t) = s0 + v0 t + a t^2 / 2 to the centroid's distance down the slope.
            const float From = 0.2f;
            double[,] ata = new double[3, 3];
            double[] atb = new double[3];
            float deepest = float.MaxValue, highestLowest = float.MinValue, worstVolume = 0f, sideways = 0f;
            Vector3 start = jelly.ComputeStats().Centroid;
            for (int n = 1; n <= steps; n++)
            {
                run.Step();
                float t = n * run.Timestep;
                SoftBodyStats s = jelly.ComputeStats();
                worstVolume = MathF.Max(worstVolume, MathF.Abs(s.VolumeRatio - 1f));
                sideways = MathF.Max(sideways, MathF.Abs(s.Centroid.Z - start.Z));
                ReadOnlySpan<Vector3> x = jelly.Positions;
                float lowest = float.MaxValue;
                for (int i = 0; i < x.Length; i++) lowest = MathF.Min(lowest, Vector3.Dot(normal, x[i]) - planeOffset);
                deepest = MathF.Min(deepest, lowest);
                if (t < From) continue;
                highestLowest = MathF.Max(highestLowest, lowest);
                double[] row = { 1, t, 0.5 * t * t };
                double along = Vector3.Dot(s.Centroid - start, down);
                for (int a = 0; a < 3; a++)
                {
                    atb[a] += row[a] * along;
                    for (int b = 0; b < 3; b++) ata[a, b] += row[a] * row[b];
                }
            }
            double acceleration = Solve3(ata, atb)[2];
            double expected = G * (MathF.Sin(theta) - Mu * MathF.Cos(theta));
            SoftBodyStats end = jelly.ComputeStats();
            TestContext.Out.WriteLine($"{scene}: acceleration down the slope {acceleration:F3} m/s^2 (fit over {From}..0.9 s) vs g(sin - mu cos) = {expected:F3}; travelled {Vector3.Dot(end.Centroid - start, down):F3} m; lowest vertex {deepest * 1000:F2} mm from the face at worst, at most {highestLowest * 1000:F2} mm above it after {From} s (collision radius {jelly.CollisionRadius * 1000:F1} mm); volume error worst {worstVolume:P2}, {MathF.Abs(end.VolumeRatio - 1):P2} at the end; min J {end.MinJ:F3}; sideways drift {sideways * 1000:F2} mm");

            Assert.That(acceleration, Is.EqualTo(expected).Within(0.02 * expected), "slides at the Coulomb rate within 2 %");
            float r = jelly.CollisionRadius;
            Assert.That(deepest, Is.GreaterThan(r - 0.002f), "no vertex closer to the face than its collision radius less 2 mm");
            Assert.That(highestLowest, Is.LessThan(r + 0.002f), "stays on the face: its lowest vertex within 2 mm of resting contact");
            Assert.That(worstVolume, Is.LessThan(0.02f), "volume within 2 %");
            Assert.That(sideways, Is.LessThan(0.005f), "no sideways drift");
        }

        // Gaussian elimination with partial pivoting for the 3x3 normal equations.
        static double[] Solve3(double[,] m, double[] r)
        {
            var a = (double[,])m.Clone();
            var b = (double[])r.Clone();
            for (int c = 0; c < 3; c++)
            {
                int p = c;
                for (int k = c + 1; k < 3; k++) if (Math.Abs(a[k, c]) > Math.Abs(a[p, c])) p = k;
                for (int k = 0; k < 3; k++) (a[c, k], a[p, k]) = (a[p, k], a[c, k]);
                (b[c], b[p]) = (b[p], b[c]);
                for (int k = c + 1; k < 3; k++)
                {
                    double f = a[k, c] / a[c, c];
                    for (int j = c; j < 3; j++) a[k, j] -= f * a[c, j];
                    b[k] -= f * b[c];
                }
            }
            var x = new double[3];
            for (int c = 2; c >= 0; c--)
            {
                double sum = b[c];
                for (int j = c + 1; j < 3; j++) sum -= a[c, j] * x[j];
                x[c] = sum / a[c, c];
            }
            return x;
        }
    }
}
