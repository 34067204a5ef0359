using System;
using System.Numerics;
using Fulcrum.Scenes;
using NUnit.Framework;
using static Fulcrum.Tests.RigidScenes.RigidSceneFiles;

namespace Fulcrum.Tests.RigidScenes
{
    /// <summary>Slopes and the bouncing ball of Samples~/Scenes against their closed forms.</summary>
    public class ContactSceneFileTests
    {
        const float G = 9.81f;
        static readonly Vector3 Downhill = Vector3.Normalize(new Vector3(-MathF.Cos(MathF.PI / 6), -MathF.Sin(MathF.PI / 6), 0));

        [Test]
        public void Box_on_30deg_slope_with_mu_0_7_stays_put_for_10_s()
        {
            // Sleeping off: measure the creep itself, not a body that went to sleep.
            WorldSettings s = WorldSettings.Default;
            s.EnableSleeping = false;
            SceneInstance scene = SceneBuilder.Build(Load("slope-mu07"), s);
            Vector3 start = Position(scene, "box");
            Run(scene, 600);
            float moved = Vector3.Dot(Position(scene, "box") - start, Downhill);
            TestContext.Out.WriteLine($"slope-mu07: moved {moved * 1000:F4} mm down the slope in 10 s");
            Assert.That(MathF.Abs(moved), Is.LessThan(0.001f));
        }

        [Test]
        public void Box_on_30deg_slope_with_mu_0_2_accelerates_at_g_sin_minus_mu_cos()
        {
            SceneInstance scene = Build("slope-mu02");
            float expected = G * (MathF.Sin(MathF.PI / 6) - 0.2f * MathF.Cos(MathF.PI / 6));
            Run(scene, 30);
            float v0 = Vector3.Dot(Velocity(scene, "box"), Downhill);
            Run(scene, 60);
            float v1 = Vector3.Dot(Velocity(scene, "box"), Downhill);
            float a = (v1 - v0) / (60 * scene.Timestep);
            TestContext.Out.WriteLine($"slope-mu02: a = {a:F4} m/s^2, closed form {expected:F4} m/s^2 ({(a / expected - 1) * 100:F2} %)");
            Assert.That(a, Is.EqualTo(expected).Within(0.02f * expected));
        }

        [Test]
        public void Ball_with_restitution_0_5_bounces_to_a_quarter_of_its_drop_height_and_comes_to_rest()
        {
            SceneInstance scene = Build("bounce"); // dropped from 8 m
            const float r = 0.25f;
            float h = Position(scene, "ball").Y - r;
            bool bounced = false;
            float apex = 0, prevVy = 0;
            int n = 0;
            for (; n < 600 && apex == 0; n++)
            {
                scene.World.Step(scene.Timestep);
                float vy = Velocity(scene, "ball").Y;
                if (vy > 0) bounced = true;
                if (bounced && prevVy > 0 && vy <= 0) apex = Position(scene, "ball").Y - r;
                prevVy = vy;
            }
            float expected = 0.25f * h;
            for (; n < 600; n++) scene.World.Step(scene.Timestep);
            float speed = Velocity(scene, "ball").Length();
            TestContext.Out.WriteLine($"bounce: first apex {apex:F4} m, e^2 h = {expected:F4} m ({(apex / expected - 1) * 100:F2} %); after 10 s speed {speed:E1} m/s, asleep {!scene.World.GetBody(scene.GetBody("ball")).IsAwake}");
            Assert.That(apex, Is.EqualTo(expected).Within(0.05f * expected));
            Assert.That(speed, Is.LessThan(1e-3f));
            Assert.That(Position(scene, "ball").Y, Is.EqualTo(r).Within(0.01f));
        }
    }
}
