using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class JellyStackTests
    {
        // jelly-stack.json: three jelly cubes (0.5, 0.4, 0.3 m; E 3e4 Pa, nu 0.48, 1000 kg/m^3,
        // 4^3 cells, damping time 0.01 s, linear damping 2 /s) dropped 1 cm onto the ground and
        // onto each other. The stiffness-proportional damping gives the stack's bobbing mode
        // (about 1.3 Hz) a damping ratio of only 0.04, so the file adds linear damping to let it
        // settle in 3 s; a damping time of 0.05 s instead makes the cubes slide off each other.
        static readonly float[] Sizes = { 0.5f, 0.4f, 0.3f };
        const float Seconds = 3f;

        [Test]
        public void Three_jelly_cubes_stack_without_interpenetrating_and_keep_their_volume()
        {
            SoftSceneRun run = SoftSceneRun.Load("jelly-stack");
            SoftBody[] cubes = run.All;
            Assert.That(cubes.Length, Is.EqualTo(3));
            int steps = run.StepsIn(Seconds);
            float worstGap = float.MaxValue, worstVolume = 0f;
            var lowGaps = new float[2];
            float topLow = float.MaxValue, topHigh = float.MinValue;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                if (n >= steps - run.StepsIn(1f))
                {
                    float y = cubes[2].ComputeStats().Centroid.Y;
                    topLow = MathF.Min(topLow, y);
                    topHigh = MathF.Max(topHigh, y);
                }
                if (n % 3 == 2)
                    for (int k = 0; k < 2; k++) worstGap = MathF.Min(worstGap, SoftGap.Min(cubes[k], cubes[k + 1]));
                foreach (SoftBody c in cubes) worstVolume = MathF.Max(worstVolume, MathF.Abs(c.ComputeStats().VolumeRatio - 1f));
            }
            var centre = new Vector3[3];
            var volume = new float[3];
            float sumSq = 0f, lowest = float.MaxValue;
            int count = 0;
            for (int k = 0; k < 3; k++)
            {
                SoftBodyStats s = cubes[k].ComputeStats();
                centre[k] = s.Centroid;
                volume[k] = s.VolumeRatio;
                ReadOnlySpan<Vector3> v = cubes[k].Velocities, x = cubes[k].Positions;
                for (int i = 0; i < v.Length; i++) { sumSq += v[i].LengthSquared(); lowest = MathF.Min(lowest, x[i].Y); }
                count += v.Length;
                if (k < 2) lowGaps[k] = SoftGap.Min(cubes[k], cubes[k + 1]);
            }
            float rmsSpeed = MathF.Sqrt(sumSq / count);
            TestContext.Out.WriteLine($"jelly-stack: centroids {centre[0]:F4} {centre[1]:F4} {centre[2]:F4} (rest heights 0.25, 0.7, 1.05); surface gaps at the end {lowGaps[0] * 1000:F2} mm, {lowGaps[1] * 1000:F2} mm, worst {worstGap * 1000:F2} mm (collision radius {cubes[0].CollisionRadius * 1000:F1} mm); volume ratios {volume[0]:F4} {volume[1]:F4} {volume[2]:F4}, worst |1 - ratio| {worstVolume:P2}; rms vertex speed at the end {rmsSpeed:F4} m/s; top centroid y in the last second {topLow:F4}..{topHigh:F4} m; lowest vertex y {lowest:F4} m");

            Assert.That(worstGap, Is.GreaterThan(-0.001f), "no surface vertex more than 1 mm inside the cube below or above");
            // Each body keeps its collision radius (5 mm) from the other's surface, so resting faces sit 10 mm apart.
            for (int k = 0; k < 2; k++) Assert.That(lowGaps[k], Is.EqualTo(2 * cubes[k].CollisionRadius).Within(0.002f), $"cube {k + 1} rests on cube {k}");
            for (int k = 0; k < 3; k++) Assert.That(volume[k], Is.EqualTo(1f).Within(0.02f), $"cube {k} keeps its volume within 2 %");
            Assert.That(worstVolume, Is.LessThan(0.05f), "within 5 % through the impacts");
            Assert.That(rmsSpeed, Is.LessThan(0.05f), "settled");
            Assert.That(topHigh - topLow, Is.LessThan(0.01f), "the top cube bobs less than 1 cm in the last second");
            float drift = new Vector2(centre[2].X - centre[0].X, centre[2].Z - centre[0].Z).Length();
            TestContext.Out.WriteLine($"jelly-stack: top centroid {drift * 1000:F1} mm off the bottom one's vertical");
            // Known limit, not physics: the stack walks diagonally along the Kuhn split's cell
            // diagonal (31 mm before the static-friction pass, 61 mm with it; the five-tet split
            // halves it). Sliding off, which this bound catches, takes the top cube > 15 cm.
            Assert.That(drift, Is.LessThan(0.08f), "the stack stays upright: top within 8 cm of the bottom's axis");
            Assert.That(lowest, Is.GreaterThan(-0.002f), "nothing through the ground");
        }
    }
}
