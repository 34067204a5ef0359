using System;
using System.Numerics;
using Fulcrum;
using NUnit.Framework;
using static Fulcrum.Tests.Solver.SolverTestScenes;

namespace Fulcrum.Tests.Solver
{
    /// <summary>
    /// The seed article's bar: towers of identical cubes on one spot, 10, 20 and 40 high, with
    /// default settings. Soft contacts sag under load (the bottom contact of a 40-box tower
    /// carries 39 boxes), so the top sinks by a bounded amount; it must not lean, drift or jitter.
    /// </summary>
    public class StackingTests
    {
        const float Dt = 1f / 60f;

        // Measured with the defaults (TGS 4x4, 60 Hz contacts, block solver, shock propagation
        // at 2 mm): top drift 0.00 mm and sag 6.9 / 26.4 / 67.0 mm for 10 / 20 / 40 boxes
        // (27.6 / 110 mm without the sweep; 26.6 / 74.4 mm before it was speculative).
        [TestCase(10, 0.002f, 0.012f)]
        [TestCase(20, 0.002f, 0.04f)]
        [TestCase(40, 0.005f, 0.09f)]
        public void Tower_of_cubes_stands_with_default_settings(int count, float maxDrift, float maxSag)
        {
            var w = new World();
            Ground(w);
            BodyHandle[] boxes = Tower(w, count);
            Vector3 top0 = w.GetBody(boxes[count - 1]).Position;
            float drift = 0;
            for (int n = 0; n < 600; n++)
            {
                w.Step(Dt);
                Vector3 d = w.GetBody(boxes[count - 1]).Position - top0;
                drift = MathF.Max(drift, new Vector2(d.X, d.Z).Length());
            }
            float sag = top0.Y - w.GetBody(boxes[count - 1]).Position.Y;
            TestContext.Out.WriteLine($"{count} boxes: top drift {drift * 1000:F2} mm, sag {sag * 1000:F1} mm, asleep {w.AwakeBodyCount == 0}");
            Assert.That(drift, Is.LessThan(maxDrift));
            Assert.That(sag, Is.InRange(0f, maxSag));
            Assert.That(w.AwakeBodyCount, Is.EqualTo(0), "a resting tower falls asleep");
        }

        [Test]
        public void Tower_of_20_rests_without_jitter_when_sleeping_is_off()
        {
            WorldSettings s = WorldSettings.Default;
            s.EnableSleeping = false;
            var w = new World(s);
            Ground(w);
            BodyHandle[] boxes = Tower(w, 20);
            for (int n = 0; n < 300; n++) w.Step(Dt);
            float jitter = 0;
            for (int n = 0; n < 60; n++)
            {
                w.Step(Dt);
                foreach (BodyHandle b in boxes) jitter = MathF.Max(jitter, w.GetBody(b).LinearVelocity.Length());
            }
            TestContext.Out.WriteLine($"largest speed in the 6th second: {jitter:E2} m/s");
            Assert.That(jitter, Is.LessThan(1e-3f));
        }

        [Test]
        public void Tower_of_40_stays_upright_for_10_s_with_sleeping_off()
        {
            WorldSettings s = WorldSettings.Default;
            s.EnableSleeping = false;
            var w = new World(s);
            Ground(w);
            BodyHandle[] boxes = Tower(w, 40);
            Vector3 top0 = w.GetBody(boxes[39]).Position;
            float drift = 0, jitter = 0;
            for (int n = 0; n < 600; n++)
            {
                w.Step(Dt);
                Vector3 d = w.GetBody(boxes[39]).Position - top0;
                drift = MathF.Max(drift, new Vector2(d.X, d.Z).Length());
                if (n >= 540) foreach (BodyHandle b in boxes) jitter = MathF.Max(jitter, w.GetBody(b).LinearVelocity.Length());
            }
            TestContext.Out.WriteLine($"40 boxes, no sleep: top drift {drift * 1000:F2} mm, largest speed in the 10th second {jitter:E2} m/s");
            Assert.That(drift, Is.LessThan(0.005f));
            Assert.That(jitter, Is.LessThan(2e-3f));
        }

        [Test]
        public void Pyramid_with_20_at_the_base_stands()
        {
            var w = new World();
            Ground(w);
            BodyHandle[] boxes = Pyramid(w, 20);
            var start = new Vector3[boxes.Length];
            for (int i = 0; i < boxes.Length; i++) start[i] = w.GetBody(boxes[i]).Position;
            for (int n = 0; n < 240; n++) w.Step(Dt);
            float worst = 0;
            for (int i = 0; i < boxes.Length; i++)
            {
                Vector3 d = w.GetBody(boxes[i]).Position - start[i];
                worst = MathF.Max(worst, new Vector2(d.X, d.Z).Length());
            }
            float topSag = start[^1].Y - w.GetBody(boxes[^1]).Position.Y;
            TestContext.Out.WriteLine($"210 boxes: largest sideways move {worst * 1000:F2} mm, top sag {topSag * 1000:F1} mm, {w.LastStepProfile.Solve:F2} ms solve in the last step");
            Assert.That(worst, Is.LessThan(0.01f));
            Assert.That(topSag, Is.InRange(0f, 0.02f));
        }

        [Test]
        public void Pgs_with_default_iterations_holds_a_tower_of_10()
        {
            var w = new World(Settings(SolverType.Pgs));
            Ground(w);
            BodyHandle[] boxes = Tower(w, 10);
            Vector3 top0 = w.GetBody(boxes[9]).Position;
            for (int n = 0; n < 600; n++) w.Step(Dt);
            Vector3 d = w.GetBody(boxes[9]).Position - top0;
            TestContext.Out.WriteLine($"PGS 10 boxes: top drift {new Vector2(d.X, d.Z).Length() * 1000:F2} mm, sag {-d.Y * 1000:F1} mm");
            Assert.That(new Vector2(d.X, d.Z).Length(), Is.LessThan(0.005f));
            Assert.That(-d.Y, Is.InRange(0f, 0.05f));
        }
    }
}
