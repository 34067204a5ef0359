using System;
using System.Numerics;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class BoxOnJellyTests
    {
        // box-on-jelly.json: a 20 kg, 0.4 m rigid box set on a 1 x 0.5 x 1 m jelly slab (E = 2e4 Pa, nu = 0.45).
        const float BoxHalf = 0.2f, Radius = 0.005f, RestTop = 0.505f;

        [Test]
        public void Rigid_box_rests_on_the_jelly_which_is_pressed_in_under_it()
        {
            SoftSceneRun run = SoftSceneRun.Load("box-on-jelly");
            var box = run.Scene.GetBody("box");
            int steps = run.StepsIn(3f);
            float yAt2 = 0f, lowestBottom = float.MaxValue;
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                float bottom = run.World.GetBody(box).Position.Y - BoxHalf;
                lowestBottom = MathF.Min(lowestBottom, bottom);
                if (n == run.StepsIn(2f)) yAt2 = run.World.GetBody(box).Position.Y;
            }
            Vector3 boxPosition = run.World.GetBody(box).Position;
            float boxBottom = boxPosition.Y - BoxHalf;
            float loadedTop = run.Body.GetProbe(0).Y, freeCorner = run.Body.GetProbe(1).Y;
            float gap = boxBottom - (loadedTop + Radius);
            TestContext.Out.WriteLine($"box-on-jelly: box bottom {boxBottom:F4} m (lowest {lowestBottom:F4}), jelly top under it {loadedTop:F4} m, free corner {freeCorner:F4} m, rest top {RestTop}");
            TestContext.Out.WriteLine($"box-on-jelly: dent under the box {freeCorner - loadedTop:F4} m, box-to-surface gap {gap:F4} m, box drift last second {boxPosition.Y - yAt2:F4} m, horizontal drift {new Vector2(boxPosition.X, boxPosition.Z).Length():F4} m, volume ratio {run.Body.ComputeStats().VolumeRatio:F4}");

            Assert.That(run.AllFinite(), Is.True);
            Assert.That(gap, Is.EqualTo(0f).Within(0.01f), "the box sits on the jelly surface, neither sunk in nor floating");
            Assert.That(lowestBottom, Is.GreaterThan(RestTop - 0.15f), "box stays above the jelly's top minus 15 cm");
            Assert.That(freeCorner - loadedTop, Is.GreaterThan(0.003f), "the jelly is pressed in under the box");
            Assert.That(loadedTop, Is.LessThan(RestTop - 0.02f), "the jelly is compressed");
            Assert.That(boxPosition.Y - yAt2, Is.EqualTo(0f).Within(0.005f), "at rest");
        }
    }
}
