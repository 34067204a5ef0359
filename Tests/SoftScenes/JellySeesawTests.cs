using System;
using System.Numerics;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class JellySeesawTests
    {
        // jelly-seesaw.json: a balanced 3 m plank on a hinge to the world (limits +-10 deg), a 0.4 m jelly cube set on it at x = 0.9 m.
        static float AngleDeg(Quaternion q) => 2f * MathF.Atan2(q.Z, q.W) * 180f / MathF.PI;

        [Test]
        public void Plank_of_a_seesaw_tips_toward_the_jelly_side_until_its_hinge_limit()
        {
            SoftSceneRun run = SoftSceneRun.Load("jelly-seesaw");
            var plank = run.Scene.GetBody("plank");
            float lowest = 0f, highest = 0f, tippedAt = float.NaN;
            int steps = run.StepsIn(2f);
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                float angle = AngleDeg(run.World.GetBody(plank).Rotation);
                lowest = MathF.Min(lowest, angle);
                highest = MathF.Max(highest, angle);
                if (float.IsNaN(tippedAt) && angle < -5f) tippedAt = (n + 1) * run.Timestep;
            }
            float end = AngleDeg(run.World.GetBody(plank).Rotation);
            Vector3 jelly = run.Body.ComputeStats().Centroid;
            TestContext.Out.WriteLine($"jelly-seesaw: plank angle end {end:F2} deg (limit -10), lowest {lowest:F2}, highest {highest:F2}, passed -5 deg at {tippedAt:F3} s; jelly centroid ({jelly.X:F3}, {jelly.Y:F3}, {jelly.Z:F3})");

            Assert.That(run.AllFinite(), Is.True);
            Assert.That(highest, Is.LessThan(0.5f), "never tips the other way");
            Assert.That(tippedAt, Is.LessThan(0.5f), "tips toward the jelly within half a second");
            Assert.That(end, Is.EqualTo(-10f).Within(1.5f), "comes to rest on its lower hinge limit");
        }
    }
}
