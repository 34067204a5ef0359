using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftScenes
{
    public class RubberOnSlabTests
    {
        // rubber-on-slab.json: a 0.3 m rubber block (E 2e6 Pa, nu 0.45, 1100 kg/m^3, Newton)
        // thrown down at 6 m/s (0.5 m/s across) onto a 1 x 0.2 x 1 m soft slab (E 2e5 Pa,
        // nu 0.49, Newton) resting on the ground; 3 s. Two Newton bodies in contact: the block's
        // step sees the slab's inertia and the slab's the block's. Before that (the pair only
        // projected after the substep), a Newton box landing on a soft slab inverted elements and
        // was thrown off (NewtonSoftContactTests).
        const float Seconds = 3f;

        [Test]
        public void A_rubber_block_thrown_onto_a_soft_slab_lands_without_inverting_and_rests_on_it()
        {
            SoftSceneRun run = SoftSceneRun.Load("rubber-on-slab");
            SoftBody slab = run.All[0], block = run.All[1];
            Assert.That(block.Solver, Is.EqualTo(SoftSolver.Newton));
            Assert.That(slab.Solver, Is.EqualTo(SoftSolver.Newton));
            float g = run.World.Gravity.Length();
            float Motion() => slab.ComputeStats().KineticEnergy + block.ComputeStats().KineticEnergy
                + g * (slab.TotalMass * slab.ComputeStats().Centroid.Y + block.TotalMass * block.ComputeStats().Centroid.Y);
            float start = Motion(), worstRise = 0f, minJ = 1f, worstGap = float.MaxValue;
            int steps = run.StepsIn(Seconds);
            for (int n = 0; n < steps; n++)
            {
                run.Step();
                worstRise = MathF.Max(worstRise, Motion() - start);
                minJ = MathF.Min(minJ, MathF.Min(slab.ComputeStats().MinJ, block.ComputeStats().MinJ));
                if (n > 10) worstGap = MathF.Min(worstGap, SoftGap.Min(slab, block));
            }
            SoftBodyStats b = block.ComputeStats();
            float endGap = SoftGap.Min(slab, block);
            float rms = 0f;
            foreach (Vector3 v in block.Velocities) rms += v.LengthSquared();
            rms = MathF.Sqrt(rms / block.VertexCount);
            TestContext.Out.WriteLine($"rubber-on-slab: min J {minJ:F3}, motion rise {worstRise:F3} J (start {start:F1} J), worst gap {worstGap * 1000:F2} mm, end gap {endGap * 1000:F2} mm, block centre {b.Centroid}, rms speed {rms:F4} m/s, block volume {b.VolumeRatio:F4}");
            Assert.That(minJ, Is.GreaterThan(0.6f), "no element near inversion");
            Assert.That(worstRise, Is.LessThan(0.5f), "kinetic and gravitational energy only fall (J)");
            Assert.That(worstGap, Is.GreaterThan(-0.003f), "the surfaces never cross by more than 3 mm");
            Assert.That(endGap, Is.EqualTo(2 * block.CollisionRadius).Within(0.003f), "the block rests on the slab");
            Assert.That(b.Centroid.Y, Is.InRange(0.35f, 0.37f), "on top: the slab's top (0.206) plus half the block and the gap");
            Assert.That(rms, Is.LessThan(0.03f), "settled (0.017 m/s measured at 3 s)");
            Assert.That(MathF.Abs(b.Centroid.X + 0.1f), Is.LessThan(0.3f), "near where it landed");
            Assert.That(b.VolumeRatio, Is.EqualTo(1f).Within(0.02f));
        }
    }
}
