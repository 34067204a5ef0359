using System;
using System.Numerics;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class JellySeesawTests
    {
        // jelly-seesaw.json: a balanced 60 kg, 3 m plank on a hinge to the world (limits +-10 deg), a 0.4 m jelly cube set on it at x = 0.9 m.
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
            // Rigid-equivalent prediction: the jelly (m, at x with its centre h above the pivot)
            // riding the plank gives alpha = m g x / (I_plank + I_jelly + m (x^2 + h^2)); -5 deg is
            // reached sqrt(2 theta / alpha) after contact, which starts once the 1 cm gap is fallen.
            float m = run.Body.TotalMass, x = 0.9f, h = 0.25f, side = 0.4f;
            float plankInertia = run.World.GetBody(plank).Mass * (3f * 3f + 0.1f * 0.1f) / 12f;
            float alpha = m * 9.81f * x / (plankInertia + m * side * side / 6f + m * (x * x + h * h));
            float predicted = MathF.Sqrt(2f * 5f * MathF.PI / 180f / alpha) + MathF.Sqrt(2f * 0.01f / 9.81f);
            Vector3 jelly = run.Body.ComputeStats().Centroid;
            TestContext.Out.WriteLine($"jelly-seesaw: plank angle end {end:F2} deg (limit -10), lowest {lowest:F2}, highest {highest:F2}, passed -5 deg at {tippedAt:F3} s (rigid-equivalent {predicted:F3} s); jelly centroid ({jelly.X:F3}, {jelly.Y:F3}, {jelly.Z:F3})");

            Assert.That(run.AllFinite(), Is.True);
            Assert.That(highest, Is.LessThan(0.5f), "never tips the other way");
            Assert.That(tippedAt, Is.EqualTo(predicted).Within(25).Percent, "tips toward the jelly as fast as its weight's torque allows");
            Assert.That(end, Is.EqualTo(-10f).Within(1.5f), "comes to rest on its lower hinge limit");
            Assert.That(jelly.X, Is.InRange(0.5f, 1.5f), "the jelly stays on the plank's low side");
            Assert.That(jelly.Y, Is.GreaterThan(0.75f), "resting on the plank, not the ground");
        }
    }
}
