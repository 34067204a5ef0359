using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// A soft bar pinned to the world by one end, too soft to hold its own weight, swinging down
    /// from horizontal: the pin carries the bar's weight, an outside load the stable Neo-Hookean
    /// energy (finite at J = 0) cannot stop short of inversion, so the volume floor must hold its
    /// tets as it holds those of a body a rigid body presses. Before the floor counted pinned
    /// bodies, the bar below went through J = 0 in 20 to 72 of its 180 steps (least J -0.17 to
    /// -0.94, both solvers), and a Newton box like soft fuzz seed 53's (E 2.8e4 Pa at 3150 kg/m³)
    /// ended the run inverted.
    /// </summary>
    public class HangingSoftTests
    {
        [Test]
        public void A_bar_too_soft_for_its_weight_swings_from_its_pin_without_inverting_an_element(
            [Values(SoftSolver.Xpbd, SoftSolver.Newton)] SoftSolver solver,
            [Values(0, 1, 2)] int materialCase)
        {
            (float youngs, float density, float nu) = materialCase switch
            {
                0 => (2e4f, 3000f, 0.2f),
                1 => (1e4f, 3000f, 0.3f),
                _ => (2e3f, 1000f, 0.3f),
            };
            var w = new World(WorldSettings.Default);
            SoftMesh mesh = SoftMesh.Box(new Vector3(1, 0.2f, 0.2f), 10, 2, 2, TetSplit.SixMirrored);
            var material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, youngs, nu, density);
            SoftBodyDef def = SoftBodyDef.Of(mesh, material, new Vector3(0, 3, 0));
            def.Solver = solver;
            // The first column of vertices (x = -0.5) pinned where it starts.
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-1, -1, -1), new Vector3(-0.45f, 1, 1)) };
            SoftBody bar = w.GetSoftBody(w.CreateSoftBody(def));
            var j = new float[bar.ElementCount];
            float least = 1, lowest = 3;
            for (int n = 0; n < 180; n++)
            {
                w.Step(1f / 60f);
                bar.ComputeElementJ(j);
                foreach (float x in j) least = MathF.Min(least, x);
                foreach (Vector3 p in bar.Positions) lowest = MathF.Min(lowest, p.Y);
            }
            Console.WriteLine($"{solver} E {youngs:G2} Pa, {density} kg/m3, nu {nu}: least J {least:F3}, lowest vertex {lowest:F2} m");
            Assert.That(SoftBodySystem.Of(w)!.DivergenceCount, Is.EqualTo(0));
            // It did swing down and stretch (the bar's free end starts at y = 2.9).
            Assert.That(lowest, Is.LessThan(2.5f), "the bar swung down");
            Assert.That(least, Is.GreaterThan(0.02f), "no element inverted at any step");
        }
    }
}
