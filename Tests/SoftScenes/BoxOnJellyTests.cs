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
            // The same slab solved statically (Newton on the total energy, same mesh and material,
            // bottom held, the box's weight as a uniform pressure on the 9 top vertices under it)
            // dents 3.7 mm; a rigid box presses its edges more and its centre less, so its dent is
            // below that. The staggered coupling before 0.4 pressed 6.6 mm (1.8 times the bound).
            float reference = UniformPressureDent();
            TestContext.Out.WriteLine($"box-on-jelly: uniform-pressure dent (Newton reference) {reference:F4} m");
            Assert.That(freeCorner - loadedTop, Is.GreaterThan(0.3f * reference).And.LessThan(1.05f * reference), "the jelly is pressed in under the box, not more than a uniform pressure would");
            Assert.That(loadedTop, Is.LessThan(RestTop - 0.02f), "the jelly is compressed");
            Assert.That(boxPosition.Y - yAt2, Is.EqualTo(0f).Within(0.005f), "at rest");
        }

        // Dent of the slab of box-on-jelly.json under the box's weight spread evenly over the top
        // vertices under it, from the static equilibrium of the same mesh (bottom pinned).
        static float UniformPressureDent()
        {
            var mesh = Fulcrum.SoftBodies.SoftMesh.Box(new Vector3(1, 0.5f, 1), 6, 3, 6);
            var material = new Fulcrum.SoftBodies.NeoHookeanMaterial(Fulcrum.SoftBodies.MaterialModel.StableNeoHookean, 2e4f, 0.45f, 1000f);
            var eq = new Fulcrum.SoftBodies.StaticEquilibrium(mesh, material);
            eq.AddGravity(new Vector3(0, -9.81f, 0));
            Vector3[] v = mesh.Vertices.ToArray();
            int under = 0, centre = -1, corner = -1;
            for (int i = 0; i < v.Length; i++)
            {
                if (v[i].Y < -0.249f) eq.Pin(i);
                if (v[i].Y > 0.249f && MathF.Abs(v[i].X) < BoxHalf && MathF.Abs(v[i].Z) < BoxHalf) under++;
                if (v[i].Y > 0.249f && MathF.Abs(v[i].X) < 1e-3f && MathF.Abs(v[i].Z) < 1e-3f) centre = i;
                if (v[i].Y > 0.249f && v[i].X > 0.49f && v[i].Z > 0.49f) corner = i;
            }
            for (int i = 0; i < v.Length; i++)
                if (v[i].Y > 0.249f && MathF.Abs(v[i].X) < BoxHalf && MathF.Abs(v[i].Z) < BoxHalf) eq.AddForce(i, new Vector3(0, -20f * 9.81f / under, 0));
            Assert.That(eq.Solve(200), Is.True, "the reference converges");
            return eq.Position(corner).Y - eq.Position(centre).Y;
        }
    }
}
