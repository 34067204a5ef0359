using System;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class EnergyGradientTests
    {
        static readonly LameParameters Lame = new LameParameters(1f, 4f);

        // Deformation gradients from mild to severe: stretch, shear, near-collapse, mirrored
        // (J < 0) and, for the classic model, below its log continuation threshold.
        static readonly Mat3[] Samples =
        {
            Mat3.FromRows(new Vector3(1.10f, 0.05f, -0.02f), new Vector3(0.03f, 0.95f, 0.10f), new Vector3(-0.04f, 0.02f, 1.05f)),
            Mat3.FromRows(new Vector3(1.60f, 0.40f, 0.10f), new Vector3(-0.20f, 0.70f, 0.30f), new Vector3(0.10f, -0.30f, 1.20f)),
            Mat3.FromRows(new Vector3(0.30f, 0.10f, 0.00f), new Vector3(0.05f, 0.25f, 0.10f), new Vector3(0.00f, 0.10f, 0.40f)),
            Mat3.FromRows(new Vector3(1.00f, 0.10f, 0.00f), new Vector3(0.00f, 1.00f, 0.20f), new Vector3(0.10f, 0.00f, -0.80f)),
            Mat3.FromRows(new Vector3(0.20f, 0.00f, 0.05f), new Vector3(0.00f, 0.30f, 0.00f), new Vector3(0.05f, 0.00f, 0.50f)),
        };

        delegate float Energy(in Mat3 f);

        static Mat3 NumericalGradient(Energy psi, Mat3 f, float step)
        {
            var g = new float[9];
            for (int k = 0; k < 9; k++)
            {
                Mat3 plus = f, minus = f;
                Nudge(ref plus, k, step);
                Nudge(ref minus, k, -step);
                g[k] = (psi(plus) - psi(minus)) / (2 * step);
            }
            return new Mat3(new Vector3(g[0], g[1], g[2]), new Vector3(g[3], g[4], g[5]), new Vector3(g[6], g[7], g[8]));
        }

        static void Nudge(ref Mat3 m, int k, float d)
        {
            Vector3 add = k % 3 == 0 ? new Vector3(d, 0, 0) : k % 3 == 1 ? new Vector3(0, d, 0) : new Vector3(0, 0, d);
            if (k / 3 == 0) m.C0 += add; else if (k / 3 == 1) m.C1 += add; else m.C2 += add;
        }

        static float MaxDifference(in Mat3 a, in Mat3 b)
        {
            Mat3 d = a - b;
            return MathF.Max(MathF.Max(Vector3.Abs(d.C0).X, MathF.Max(Vector3.Abs(d.C0).Y, Vector3.Abs(d.C0).Z)),
                MathF.Max(MathF.Max(MathF.Abs(d.C1.X), MathF.Max(MathF.Abs(d.C1.Y), MathF.Abs(d.C1.Z))), MathF.Max(MathF.Abs(d.C2.X), MathF.Max(MathF.Abs(d.C2.Y), MathF.Abs(d.C2.Z)))));
        }

        [Test]
        public void Stable_stress_is_the_gradient_of_the_energy([Range(0, 4)] int sample)
        {
            var energy = new StableNeoHookeanEnergy(Lame);
            Mat3 f = Samples[sample];
            Mat3 numeric = NumericalGradient((in Mat3 x) => energy.EnergyDensity(x), f, 1e-3f);
            Assert.That(MaxDifference(energy.FirstPiolaStress(f), numeric), Is.LessThan(2e-3f));
        }

        [Test]
        public void Classic_stress_is_the_gradient_of_the_energy_including_below_min_J([Range(0, 4)] int sample)
        {
            var energy = new NeoHookeanEnergy(Lame);
            Mat3 f = Samples[sample];
            Mat3 numeric = NumericalGradient((in Mat3 x) => energy.EnergyDensity(x), f, 1e-3f);
            Assert.That(MaxDifference(energy.FirstPiolaStress(f), numeric), Is.LessThan(2e-3f * MathF.Max(1f, numeric.FrobeniusSquared)));
        }

        [Test]
        public void Stable_energy_is_finite_and_restoring_for_inverted_and_collapsed_elements()
        {
            var energy = new StableNeoHookeanEnergy(Lame);
            Assert.That(energy.EnergyDensity(Mat3.Zero), Is.GreaterThan(0f).And.LessThan(100f));
            Mat3 mirrored = Mat3.Diagonal(new Vector3(1, 1, -1));
            Assert.That(float.IsFinite(energy.EnergyDensity(mirrored)), Is.True);
            Assert.That(energy.EnergyDensity(mirrored), Is.GreaterThan(energy.EnergyDensity(Mat3.Identity)));
            Assert.That(energy.EnergyDensity(Mat3.Identity), Is.EqualTo(0f).Within(1e-6f));
            Assert.That(MaxDifference(energy.FirstPiolaStress(Mat3.Identity), Mat3.Zero), Is.LessThan(1e-6f));
        }

        [Test]
        public void Constraint_split_reproduces_the_energy([Range(0, 4)] int sample)
        {
            Mat3 f = Samples[sample];
            var stable = new StableNeoHookeanEnergy(Lame);
            stable.Constraints(f, out float cD, out _, out float cH, out _);
            Assert.That(0.5f * stable.DeviatoricStiffness * cD * cD + 0.5f * stable.HydrostaticStiffness * cH * cH,
                Is.EqualTo(stable.EnergyDensity(f)).Within(1e-4f * MathF.Max(1f, stable.EnergyDensity(f))));
            var classic = new NeoHookeanEnergy(Lame);
            classic.Constraints(f, out cD, out _, out cH, out _);
            Assert.That(0.5f * classic.DeviatoricStiffness * cD * cD + 0.5f * classic.HydrostaticStiffness * cH * cH,
                Is.EqualTo(classic.EnergyDensity(f)).Within(1e-4f * MathF.Max(1f, classic.EnergyDensity(f))));
        }

        [Test]
        public void Constraint_gradients_match_finite_differences([Range(0, 4)] int sample, [Values] MaterialModel model)
        {
            Mat3 f = Samples[sample];
            IHyperelasticModel m = model == MaterialModel.NeoHookean ? new NeoHookeanEnergy(Lame) : new StableNeoHookeanEnergy(Lame);
            m.Constraints(f, out _, out Mat3 dD, out _, out Mat3 dH);
            Mat3 numD = NumericalGradient((in Mat3 x) => { m.Constraints(x, out float c, out _, out _, out _); return c; }, f, 1e-3f);
            Mat3 numH = NumericalGradient((in Mat3 x) => { m.Constraints(x, out _, out _, out float c, out _); return c; }, f, 1e-3f);
            Assert.That(MaxDifference(dD, numD), Is.LessThan(3e-3f), "deviatoric");
            Assert.That(MaxDifference(dH, numH), Is.LessThan(3e-3f * MathF.Max(1f, MathF.Sqrt(numH.FrobeniusSquared))), "hydrostatic");
        }

        [Test]
        public void Both_constraints_vanish_exactly_at_rest([Values] MaterialModel model)
        {
            IHyperelasticModel m = model == MaterialModel.NeoHookean ? new NeoHookeanEnergy(Lame) : new StableNeoHookeanEnergy(Lame);
            m.Constraints(Mat3.Identity, out float cD, out _, out float cH, out _);
            Assert.That(cD, Is.EqualTo(0f));
            Assert.That(cH, Is.EqualTo(0f));
        }

        [Test]
        public void Vertex_forces_are_minus_the_gradient_of_the_body_energy([Values] MaterialModel model)
        {
            var world = SoftBodyScenes.ZeroGravityWorld();
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(1f), 1, 1, 1), new NeoHookeanMaterial(model, 10f, 0.3f, 1f), Vector3.Zero);
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            var random = new Random(7);
            for (int i = 0; i < body.VertexCount; i++)
                body.SetVertexPosition(i, body.Positions[i] * 1.1f + new Vector3((float)random.NextDouble(), (float)random.NextDouble(), (float)random.NextDouble()) * 0.15f);
            var forces = new Vector3[body.VertexCount];
            body.ComputeElasticForces(forces);
            const float h = 1e-3f;
            for (int i = 0; i < body.VertexCount; i++)
                for (int axis = 0; axis < 3; axis++)
                {
                    Vector3 x = body.Positions[i];
                    Vector3 d = axis == 0 ? new Vector3(h, 0, 0) : axis == 1 ? new Vector3(0, h, 0) : new Vector3(0, 0, h);
                    body.SetVertexPosition(i, x + d);
                    float plus = body.ComputeStats().StrainEnergy;
                    body.SetVertexPosition(i, x - d);
                    float minus = body.ComputeStats().StrainEnergy;
                    body.SetVertexPosition(i, x);
                    float component = axis == 0 ? forces[i].X : axis == 1 ? forces[i].Y : forces[i].Z;
                    Assert.That(component, Is.EqualTo(-(plus - minus) / (2 * h)).Within(2e-3f), $"vertex {i} axis {axis}");
                }
        }

        [Test]
        public void Dihedral_angle_gradient_matches_finite_differences()
        {
            Vector3 a = new Vector3(0.4f, -1f, 0.3f), b = new Vector3(0.6f, 1f, -0.5f), c = new Vector3(0, 0, 0), d = new Vector3(1f, 0.1f, 0.05f);
            Assert.That(DihedralAngle.WithGradient(a, b, c, d, out float angle, out Vector3 ga, out Vector3 gb, out Vector3 gc, out Vector3 gd), Is.True);
            Assert.That(angle, Is.EqualTo(DihedralAngle.Of(a, b, c, d)).Within(1e-6f));
            Vector3[] p = { a, b, c, d };
            Vector3[] g = { ga, gb, gc, gd };
            const float h = 1e-3f;
            for (int v = 0; v < 4; v++)
                for (int axis = 0; axis < 3; axis++)
                {
                    Vector3 e = axis == 0 ? new Vector3(h, 0, 0) : axis == 1 ? new Vector3(0, h, 0) : new Vector3(0, 0, h);
                    Vector3[] q = (Vector3[])p.Clone();
                    q[v] += e;
                    float plus = DihedralAngle.Of(q[0], q[1], q[2], q[3]);
                    q[v] -= 2 * e;
                    float minus = DihedralAngle.Of(q[0], q[1], q[2], q[3]);
                    float component = axis == 0 ? g[v].X : axis == 1 ? g[v].Y : g[v].Z;
                    Assert.That(component, Is.EqualTo((plus - minus) / (2 * h)).Within(1e-3f), $"vertex {v} axis {axis}");
                }
        }

        [Test]
        public void Membrane_constraint_gradients_match_finite_differences([Values] MaterialModel model)
        {
            var energy = new MembraneEnergy(new NeoHookeanMaterial(model, 1f, 0.3f, 1f));
            Vector3 f0 = new Vector3(1.2f, 0.1f, -0.2f), f1 = new Vector3(0.1f, 0.8f, 0.3f);
            energy.Constraints(f0, f1, out float cD, out Vector3 d0, out Vector3 d1, out float cH, out Vector3 h0, out Vector3 h1);
            Assert.That(0.5f * energy.Mu * cD * cD + 0.5f * energy.Lambda * cH * cH, Is.EqualTo(energy.EnergyDensity(f0, f1)).Within(1e-4f));
            const float step = 1e-3f;
            for (int col = 0; col < 2; col++)
                for (int axis = 0; axis < 3; axis++)
                {
                    Vector3 e = axis == 0 ? new Vector3(step, 0, 0) : axis == 1 ? new Vector3(0, step, 0) : new Vector3(0, 0, step);
                    Vector3 a0 = col == 0 ? f0 + e : f0, a1 = col == 1 ? f1 + e : f1;
                    Vector3 b0 = col == 0 ? f0 - e : f0, b1 = col == 1 ? f1 - e : f1;
                    energy.Constraints(a0, a1, out float dPlus, out _, out _, out float hPlus, out _, out _);
                    energy.Constraints(b0, b1, out float dMinus, out _, out _, out float hMinus, out _, out _);
                    Vector3 gd = col == 0 ? d0 : d1, gh = col == 0 ? h0 : h1;
                    float cd = axis == 0 ? gd.X : axis == 1 ? gd.Y : gd.Z, ch = axis == 0 ? gh.X : axis == 1 ? gh.Y : gh.Z;
                    Assert.That(cd, Is.EqualTo((dPlus - dMinus) / (2 * step)).Within(2e-3f), $"deviatoric f{col} axis {axis}");
                    Assert.That(ch, Is.EqualTo((hPlus - hMinus) / (2 * step)).Within(2e-3f), $"area f{col} axis {axis}");
                }
        }
    }
}
