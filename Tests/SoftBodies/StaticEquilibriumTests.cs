using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// The Newton static-equilibrium reference against closed forms: a homogeneous uniaxial
    /// stretch with free lateral faces (which linear tets represent exactly, so the mesh must
    /// reproduce the closed-form lateral stretch to solver precision), nearly incompressible
    /// included, and the clamped stiff bar under its own weight.
    /// </summary>
    public class StaticEquilibriumTests
    {
        [TestCase(MaterialModel.StableNeoHookean, 0.3f, 1.3)]
        [TestCase(MaterialModel.StableNeoHookean, 0.4999f, 1.3)]
        [TestCase(MaterialModel.StableNeoHookean, 0.3f, 0.8)]
        [TestCase(MaterialModel.NeoHookean, 0.3f, 1.3)]
        [TestCase(MaterialModel.NeoHookean, 0.4999f, 0.8)]
        public void UniaxialStretchMatchesClosedForm(MaterialModel model, float nu, double stretch)
        {
            var material = new NeoHookeanMaterial(model, 1e5f, nu, 1000f);
            SoftMesh mesh = SoftMesh.Box(Vector3.One, 2, 2, 2);
            var eq = new StaticEquilibrium(mesh, material);
            ReadOnlySpan<Vector3> v = mesh.Vertices;
            int corner = -1, side = -1;
            for (int i = 0; i < v.Length; i++)
            {
                // Both x faces held in x only (they slide freely in y and z); one corner fixed in
                // y and z and a second vertex on that face in z remove the remaining rigid motions.
                if (v[i].X < -0.49f) eq.Fix(i, 0, -0.5);
                if (v[i].X > 0.49f) eq.Fix(i, 0, -0.5 + stretch);
                if (v[i].X < -0.49f && v[i].Y < -0.49f && v[i].Z < -0.49f) corner = i;
                if (v[i].X < -0.49f && v[i].Y > 0.49f && v[i].Z < -0.49f) side = i;
            }
            eq.Fix(corner, 1, -0.5);
            eq.Fix(corner, 2, -0.5);
            eq.Fix(side, 2, -0.5);

            Assert.That(eq.Solve(), Is.True, $"Newton did not converge: residual {eq.Residual} N after {eq.Iterations} iterations");

            double lateral = LateralStretch(material, stretch);
            double minY = double.MaxValue, maxY = double.MinValue, minZ = double.MaxValue, maxZ = double.MinValue;
            for (int i = 0; i < v.Length; i++)
            {
                Vector3 p = eq.Position(i);
                minY = Math.Min(minY, p.Y); maxY = Math.Max(maxY, p.Y); minZ = Math.Min(minZ, p.Z); maxZ = Math.Max(maxZ, p.Z);
            }
            TestContext.Out.WriteLine($"{model} nu {nu} stretch {stretch}: lateral {maxY - minY:F6} / {maxZ - minZ:F6} vs closed form {lateral:F6}, J {stretch * lateral * lateral:F5}, {eq.Iterations} Newton iterations");
            Assert.That(maxY - minY, Is.EqualTo(lateral).Within(1e-5));
            Assert.That(maxZ - minZ, Is.EqualTo(lateral).Within(1e-5));
            if (nu > 0.49f) Assert.That(stretch * lateral * lateral, Is.EqualTo(1.0).Within(2e-3), "nearly incompressible: volume kept");
        }

        /// <summary>
        /// F = diag(s, t, t) with zero lateral stress P_yy = 0, solved for t by bisection.
        /// Stable Neo-Hookean: mu I_C/(I_C + 1) t + lambda (J - alpha) s t = 0;
        /// classic: mu t + (lambda ln J - mu) / t = 0; J = s t^2.
        /// </summary>
        static double LateralStretch(in NeoHookeanMaterial material, double s)
        {
            double mu, lambda, alpha = 0;
            bool stable = material.Model == MaterialModel.StableNeoHookean;
            if (stable)
            {
                StableNeoHookeanEnergy e = StableNeoHookeanEnergy.Of(material);
                mu = e.Mu; lambda = e.Lambda; alpha = 1 + 0.75 * mu / lambda;
            }
            else
            {
                mu = material.LinearLame.Mu; lambda = material.LinearLame.Lambda;
            }
            double Pyy(double t)
            {
                double j = s * t * t, ic = s * s + 2 * t * t;
                return stable ? mu * ic / (ic + 1) * t + lambda * (j - alpha) * s * t : mu * t + (lambda * Math.Log(j) - mu) / t;
            }
            double lo = 0.05, hi = 3;
            for (int k = 0; k < 200; k++)
            {
                double mid = 0.5 * (lo + hi);
                if (Pyy(mid) > 0) hi = mid; else lo = mid;
            }
            return 0.5 * (lo + hi);
        }

        [Test]
        public void RefinedBarApproachesBeamTheory()
        {
            // Same bar, E = 1e7 Pa (small deflection), nu = 0: the sag of linear tets rises towards
            // Euler-Bernoulli qL^4/8EI as the cross-section is refined (one cell across locks).
            var material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e7f, 0f, 1000f);
            double beam = 1000 * 9.81 * 0.01 / (8 * 1e7 * Math.Pow(0.1, 4) / 12);
            double coarse = BarSag(material, 10, 1), fine = BarSag(material, 20, 2);
            TestContext.Out.WriteLine($"bar E 1e7: sag 10x1x1 {coarse * 1e3:F3} mm, 20x2x2 {fine * 1e3:F3} mm, Euler-Bernoulli {beam * 1e3:F3} mm");
            Assert.That(fine, Is.GreaterThan(coarse));
            Assert.That(Math.Abs(fine - beam), Is.LessThan(Math.Abs(coarse - beam)));
            Assert.That(fine, Is.LessThan(1.1 * beam));
        }

        static double BarSag(in NeoHookeanMaterial material, int cellsLong, int cellsAcross)
        {
            SoftMesh mesh = SoftMesh.Box(new Vector3(1f, 0.1f, 0.1f), cellsLong, cellsAcross, cellsAcross);
            var eq = new StaticEquilibrium(mesh, material);
            ReadOnlySpan<Vector3> v = mesh.Vertices;
            for (int i = 0; i < v.Length; i++) if (v[i].X < -0.499f) eq.Pin(i);
            eq.AddGravity(new Vector3(0, -9.81f, 0));
            Assert.That(eq.Solve(30, 1e-6), Is.True, $"residual {eq.Residual} N after {eq.Iterations} iterations");
            double sag = 0;
            int tip = 0;
            for (int i = 0; i < v.Length; i++)
                if (v[i].X > 0.499f) { sag += v[i].Y - eq.Position(i).Y; tip++; }
            return sag / tip;
        }

        [Test]
        public void StiffBarSagIsBelowAMillimetre()
        {
            // stiff-bar.json's body: 1 x 0.1 x 0.1 m, 10 x 1 x 1 cells, E = 1e9 Pa, clamped at x = -0.5.
            var material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e9f, 0.3f, 1000f);
            SoftMesh mesh = SoftMesh.Box(new Vector3(1f, 0.1f, 0.1f), 10, 1, 1);
            var eq = new StaticEquilibrium(mesh, material);
            ReadOnlySpan<Vector3> v = mesh.Vertices;
            for (int i = 0; i < v.Length; i++) if (v[i].X < -0.499f) eq.Pin(i);
            eq.AddGravity(new Vector3(0, -9.81f, 0));
            Assert.That(eq.Solve(), Is.True, $"residual {eq.Residual} N after {eq.Iterations} iterations");
            double sag = 0;
            int tip = 0;
            for (int i = 0; i < v.Length; i++)
                if (v[i].X > 0.499f) { sag += v[i].Y - eq.Position(i).Y; tip++; }
            sag /= tip;
            double beam = 1000 * 9.81 * 0.01 * Math.Pow(1, 4) / (8 * 1e9 * Math.Pow(0.1, 4) / 12);
            TestContext.Out.WriteLine($"stiff-bar Newton reference: tip sag {sag * 1e3:F4} mm vs Euler-Bernoulli {beam * 1e3:F4} mm, {eq.Iterations} iterations");
            // Linear tets on one cell across lock in bending: stiffer than the beam, same order.
            Assert.That(sag, Is.GreaterThan(0.05 * beam).And.LessThan(beam));
        }
    }
}
