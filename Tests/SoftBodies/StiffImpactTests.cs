using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// Stiff boxes (E 1e5 to 1e10 Pa) of every proportion and cell count, turned at random and
    /// dropped from 1.5 m onto the ground (landing at up to 5.4 m/s), with the XPBD solver at its
    /// defaults. Gauss-Seidel XPBD cannot resolve such an impact within a step at these moduli
    /// (the elements are crushed to J 0.6-0.7 before they push back), so what must hold is
    /// robustness: no body diverges, no element ends inverted, and the motion (kinetic and
    /// gravitational energy) never grows.
    /// With the classic Neo-Hookean energy 1 to 2 of each 40 drops diverged before its
    /// projection was given a trust region (XpbdTetSolver.LimitReach; soft fuzz seed 639).
    /// </summary>
    public class StiffImpactTests
    {
        struct Drop
        {
            public bool Diverged;
            public float EndMinJ, MotionRise;
        }

        static Drop Run(SoftMesh mesh, Quaternion turn, in NeoHookeanMaterial material)
        {
            World world = SoftBodyScenes.WorldWithGround();
            var def = SoftBodyDef.Of(mesh, material, new Vector3(0, 1.5f, 0));
            def.Rotation = turn;
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            SoftBodySystem system = SoftBodySystem.Of(world)!;
            float Motion()
            {
                SoftBodyStats s = body.ComputeStats();
                return s.KineticEnergy - body.TotalMass * Vector3.Dot(world.Gravity, s.Centroid);
            }
            float start = Motion();
            var drop = new Drop();
            for (int i = 0; i < 90; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                if (system.DivergenceCount > 0)
                {
                    drop.Diverged = true;
                    return drop;
                }
                drop.MotionRise = MathF.Max(drop.MotionRise, Motion() - start);
            }
            drop.EndMinJ = body.ComputeStats().MinJ;
            return drop;
        }

        [Test]
        public void A_stiff_box_dropped_at_any_pose_never_blows_up(
            [Values(MaterialModel.NeoHookean, MaterialModel.StableNeoHookean)] MaterialModel model, [Values(0.3f, 0.49f, 0.4999f)] float poisson)
        {
            var random = new Random(7);
            float Next() => (float)random.NextDouble();
            int diverged = 0, inverted = 0, gained = 0;
            string failures = "";
            for (int k = 0; k < 40; k++)
            {
                float youngs = MathF.Pow(10f, 5f + 5f * Next());
                var split = (TetSplit)random.Next(3);
                var size = new Vector3(0.1f + 0.9f * Next(), 0.05f + 0.55f * Next(), 0.1f + 0.9f * Next());
                int nx = 1 + random.Next(5), ny = 1 + random.Next(4), nz = 1 + random.Next(5);
                var turn = Quaternion.Normalize(new Quaternion(Next() - 0.5f, Next() - 0.5f, Next() - 0.5f, Next() - 0.5f));
                Drop d = Run(SoftMesh.Box(size, nx, ny, nz, split), turn, new NeoHookeanMaterial(model, youngs, poisson, 1000f));
                string what = $" [{k}: E {youngs:G2} {size.X:F2}x{size.Y:F2}x{size.Z:F2} m {nx}x{ny}x{nz} {split}";
                if (d.Diverged) { diverged++; failures += what + " diverged]"; }
                else if (d.EndMinJ <= 0f) { inverted++; failures += what + $" min J {d.EndMinJ:F2}]"; }
                else if (d.MotionRise > 0.5f) { gained++; failures += what + $" motion rose {d.MotionRise:G3} J]"; }
            }
            TestContext.Out.WriteLine($"{model} nu {poisson}: {diverged} diverged, {inverted} inverted, {gained} gained energy of 40{failures}");
            Assert.That(diverged + inverted + gained, Is.Zero, failures);
        }

        // The reduced reproducer of soft fuzz seed 639: one row of five thin cells, landing on an
        // edge; it diverged at every E from 3.5e8 Pa on before the trust region.
        [TestCase(3.5e8f), TestCase(1e9f), TestCase(1e10f)]
        public void A_stiff_classic_neo_hookean_bar_landing_on_an_edge_stays_whole(float youngs)
        {
            var turn = Quaternion.Normalize(new Quaternion(-0.683059f, -0.471873f, -0.075668f, -0.552306f));
            var mesh = SoftMesh.Box(new Vector3(0.18794f, 0.15720f, 0.24151f), 1, 1, 5, TetSplit.SixMirrored);
            Drop d = Run(mesh, turn, new NeoHookeanMaterial(MaterialModel.NeoHookean, youngs, 0.3f, 1000f));
            TestContext.Out.WriteLine($"E {youngs:G2}: diverged {d.Diverged}, end min J {d.EndMinJ:F3}, motion rise {d.MotionRise:G3} J");
            Assert.That(d.Diverged, Is.False);
            Assert.That(d.EndMinJ, Is.GreaterThan(0.5f));
            Assert.That(d.MotionRise, Is.LessThan(0.5f));
        }
    }
}
