using System;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// A bar stretched by its clamped ends. Far from the clamps the state is uniaxial:
    /// F = diag(a, b, b) with zero lateral stress. Closed forms for the lateral stretch b(a):
    /// classic, P_yy = mu (b - 1/b) + lambda ln(a b^2) / b = 0, i.e. mu (b^2 - 1) + lambda ln(a b^2) = 0;
    /// stable, P_yy = mu b (1 - 1/(I_C + 1)) + lambda (a b^2 - alpha) a b = 0 with I_C = a^2 + 2 b^2,
    /// i.e. mu (1 - 1/(a^2 + 2 b^2 + 1)) + lambda a (a b^2 - alpha) = 0 (energy Lame parameters).
    /// Both are solved by bisection on b in (0, 2).
    /// </summary>
    public class UniaxialTests
    {
        public static double LateralStretch(MaterialModel model, in NeoHookeanMaterial m, double a)
        {
            LameParameters lame = m.EnergyLame;
            double mu = lame.Mu, lambda = lame.Lambda, alpha = 1 + 0.75 * mu / lambda;
            Func<double, double> residual = model == MaterialModel.NeoHookean
                ? b => mu * (b * b - 1) + lambda * Math.Log(a * b * b)
                : b => mu * (1 - 1 / (a * a + 2 * b * b + 1)) + lambda * a * (a * b * b - alpha);
            double lo = 1e-3, hi = 2;
            for (int i = 0; i < 200; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (residual(mid) < 0) lo = mid; else hi = mid;
            }
            return 0.5 * (lo + hi);
        }

        internal static SoftBody StretchedBar(MaterialModel model, float nu, float stretch, int steps, out World world, SoftSolver solver = SoftSolver.Xpbd)
        {
            world = SoftBodyScenes.ZeroGravityWorld();
            var material = new NeoHookeanMaterial(model, 1e5f, nu, 1000f);
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(1.2f, 0.2f, 0.2f), 18, 3, 3), material, Vector3.Zero);
            def.InitialDeformation = Mat3.Diagonal(new Vector3(stretch, 1, 1));
            def.Pins = new[]
            {
                SoftPin.ToWorld(new Vector3(-0.6f, -1, -1), new Vector3(-0.6f, 1, 1)),
                SoftPin.ToWorld(new Vector3(0.6f, -1, -1), new Vector3(0.6f, 1, 1)),
            };
            // Middle cross-section: axial gauge +-0.1 m, lateral gauges across the full width.
            def.Probes = new[]
            {
                new Vector3(-0.1f, 0, 0), new Vector3(0.1f, 0, 0),
                new Vector3(0, -0.1f, 0), new Vector3(0, 0.1f, 0),
                new Vector3(0, 0, -0.1f), new Vector3(0, 0, 0.1f),
            };
            def.Substeps = solver == SoftSolver.Newton ? 0 : 20;
            def.Iterations = solver == SoftSolver.Newton ? 1 : 2;
            def.DampingTime = 0.02f;
            def.Solver = solver;
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            for (int i = 0; i < steps; i++) world.Step(SoftBodyScenes.Dt);
            return body;
        }

        [TestCase(MaterialModel.NeoHookean, 0.3f, 1.3f)]
        [TestCase(MaterialModel.StableNeoHookean, 0.3f, 1.3f)]
        [TestCase(MaterialModel.StableNeoHookean, 0.45f, 1.5f)]
        public void Bar_lateral_stretch_matches_the_uniaxial_closed_form(MaterialModel model, float nu, float stretch)
        {
            SoftBody bar = StretchedBar(model, nu, stretch, 150, out _);
            float a = (bar.GetProbe(1) - bar.GetProbe(0)).Length() / 0.2f;
            float by = (bar.GetProbe(3) - bar.GetProbe(2)).Length() / 0.2f;
            float bz = (bar.GetProbe(5) - bar.GetProbe(4)).Length() / 0.2f;
            double expected = LateralStretch(model, bar.Material, a);
            TestContext.Out.WriteLine($"{model} nu={nu}: axial {a:F4}, lateral {by:F4} {bz:F4}, closed form {expected:F4}, linear guess {1 - nu * (a - 1):F4}");
            // The clamps hold the ends' cross-sections, so the middle stretches a little more than the ends' mean.
            Assert.That(a, Is.EqualTo(stretch).Within(0.05f * stretch), "axial stretch in the middle");
            Assert.That(by, Is.EqualTo(expected).Within(0.002));
            Assert.That(bz, Is.EqualTo(expected).Within(0.002));
        }

        [TestCase(MaterialModel.StableNeoHookean)]
        [TestCase(MaterialModel.NeoHookean)]
        public void Nearly_incompressible_bar_keeps_its_volume_within_one_percent(MaterialModel model)
        {
            SoftBody bar = StretchedBar(model, 0.49f, 1.3f, 150, out _);
            float a = (bar.GetProbe(1) - bar.GetProbe(0)).Length() / 0.2f;
            float by = (bar.GetProbe(3) - bar.GetProbe(2)).Length() / 0.2f;
            float bz = (bar.GetProbe(5) - bar.GetProbe(4)).Length() / 0.2f;
            double b = LateralStretch(model, bar.Material, a);
            SoftBodyStats stats = bar.ComputeStats();
            TestContext.Out.WriteLine($"{model}: middle J {a * by * bz:F4} (closed form {a * b * b:F4}), body volume ratio {stats.VolumeRatio:F4}, J in [{stats.MinJ:F4}, ..]");
            Assert.That(a * by * bz, Is.EqualTo(1f).Within(0.01f), "J in the middle");
            // Linear tets near incompressibility are slightly too stiff in volume (locking): 0.4% here.
            Assert.That(a * by * bz, Is.EqualTo(a * b * b).Within(0.005), "J against the closed form");
            Assert.That(stats.VolumeRatio, Is.EqualTo(1f).Within(0.01f), "whole bar");
            // The clamped corners concentrate strain; no element may lose more than 15%.
            Assert.That(stats.MinJ, Is.GreaterThan(0.85f));
        }
    }
}
