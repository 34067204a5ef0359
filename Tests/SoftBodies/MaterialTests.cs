using System;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class MaterialTests
    {
        static Mat3 FirstPiola(in NeoHookeanMaterial m, in Mat3 f) =>
            m.Model == MaterialModel.NeoHookean ? NeoHookeanEnergy.Of(m).FirstPiolaStress(f) : StableNeoHookeanEnergy.Of(m).FirstPiolaStress(f);

        // A uniaxial small strain d with the lateral contraction -nu d is the state of a bar in
        // tension: linear elasticity gives sigma_xx = E d and no lateral stress. Both energies,
        // each with its own Lame mapping, must reproduce that at small strain.
        [TestCase(MaterialModel.NeoHookean, 1e5f, 0.3f)]
        [TestCase(MaterialModel.NeoHookean, 1e6f, 0.45f)]
        [TestCase(MaterialModel.StableNeoHookean, 1e5f, 0.3f)]
        [TestCase(MaterialModel.StableNeoHookean, 1e6f, 0.45f)]
        [TestCase(MaterialModel.StableNeoHookean, 1e4f, -0.3f)]
        public void Small_uniaxial_strain_reproduces_E_and_nu(MaterialModel model, float e, float nu)
        {
            var m = new NeoHookeanMaterial(model, e, nu, 1000f);
            const float d = 1e-3f;
            Mat3 p = FirstPiola(m, Mat3.Diagonal(new Vector3(1 + d, 1 - nu * d, 1 - nu * d)));
            Assert.That(p[0, 0] / (e * d), Is.EqualTo(1.0).Within(0.01), "axial stress / (E strain)");
            Assert.That(p[1, 1] / (e * d), Is.EqualTo(0.0).Within(0.01), "lateral stress / (E strain)");
            Assert.That(p[2, 2] / (e * d), Is.EqualTo(0.0).Within(0.01), "lateral stress / (E strain)");
        }

        [TestCase(MaterialModel.NeoHookean)]
        [TestCase(MaterialModel.StableNeoHookean)]
        public void Small_shear_reproduces_the_shear_modulus(MaterialModel model)
        {
            var m = new NeoHookeanMaterial(model, 2e5f, 0.4f, 1000f);
            const float g = 1e-3f;
            var f = new Mat3(Vector3.UnitX, new Vector3(g, 1, 0), Vector3.UnitZ);
            float mu = 2e5f / (2 * 1.4f);
            Assert.That(FirstPiola(m, f)[0, 1] / (mu * g), Is.EqualTo(1.0).Within(0.01));
        }

        [Test]
        public void Stable_mapping_is_the_one_of_Smith_et_al()
        {
            var linear = new LameParameters(3f, 7f);
            LameParameters s = LameParameters.ForStableNeoHookean(linear);
            Assert.That(s.Mu, Is.EqualTo(4f).Within(1e-6f));
            Assert.That(s.Lambda, Is.EqualTo(7f + 2.5f).Within(1e-6f));
            Assert.That(new StableNeoHookeanEnergy(s).Alpha, Is.EqualTo(1f + 0.75f * 4f / 9.5f).Within(1e-6f));
        }

        [Test]
        public void Lame_parameters_round_trip_through_E_and_nu()
        {
            LameParameters l = LameParameters.FromYoungPoisson(1e6f, 0.3f);
            Assert.That(l.Mu, Is.EqualTo(1e6f / 2.6f).Within(1f));
            Assert.That(l.Lambda, Is.EqualTo(1e6f * 0.3f / (1.3f * 0.4f)).Within(1f));
            Assert.That(l.YoungsModulus, Is.EqualTo(1e6f).Within(1f));
            Assert.That(l.PoissonRatio, Is.EqualTo(0.3f).Within(1e-6f));
            NeoHookeanMaterial m = NeoHookeanMaterial.FromLame(MaterialModel.NeoHookean, l.Mu, l.Lambda, 900f);
            Assert.That(m.YoungsModulus, Is.EqualTo(1e6f).Within(1f));
            Assert.That(m.PoissonRatio, Is.EqualTo(0.3f).Within(1e-6f));
        }

        [Test]
        public void Presets_are_valid_SI_materials()
        {
            foreach (NeoHookeanMaterial m in new[] { MaterialPresets.Jelly, MaterialPresets.Rubber, MaterialPresets.Cloth, MaterialPresets.Slime, MaterialPresets.SoftTissue })
            {
                Assert.DoesNotThrow(() => m.Validate(), m.ToString());
                Assert.That(m.Density, Is.InRange(300f, 1200f), m.ToString());
            }
            Assert.That(MaterialPresets.Rubber.YoungsModulus, Is.GreaterThan(MaterialPresets.Jelly.YoungsModulus));
            Assert.That(MaterialPresets.Slime.YoungsModulus, Is.LessThan(MaterialPresets.Jelly.YoungsModulus));
        }

        [Test]
        public void Scene_file_model_names_map_both_ways()
        {
            Assert.That(NeoHookeanMaterial.ParseModel("stable-neo-hookean"), Is.EqualTo(MaterialModel.StableNeoHookean));
            Assert.That(NeoHookeanMaterial.ParseModel("neo-hookean"), Is.EqualTo(MaterialModel.NeoHookean));
            Assert.That(NeoHookeanMaterial.ModelName(MaterialModel.NeoHookean), Is.EqualTo("neo-hookean"));
            Assert.That(NeoHookeanMaterial.ModelName(MaterialModel.StableNeoHookean), Is.EqualTo("stable-neo-hookean"));
            var ex = Assert.Throws<ArgumentException>(() => NeoHookeanMaterial.ParseModel("hookean"));
            Assert.That(ex!.ParamName, Is.EqualTo("material.model"));
        }

        [TestCase(0.5f, "material.PoissonRatio")]
        [TestCase(0.6f, "material.PoissonRatio")]
        [TestCase(-1f, "material.PoissonRatio")]
        [TestCase(float.NaN, "material.PoissonRatio")]
        public void Poisson_ratio_outside_minus_one_to_half_is_rejected(float nu, string field)
        {
            var m = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, nu, 1000f);
            var ex = Assert.Throws<ArgumentException>(() => m.Validate());
            Assert.That(ex!.ParamName, Is.EqualTo(field));
        }

        [TestCase(0f, 1000f, "material.YoungsModulus")]
        [TestCase(-5f, 1000f, "material.YoungsModulus")]
        [TestCase(float.PositiveInfinity, 1000f, "material.YoungsModulus")]
        [TestCase(1e5f, 0f, "material.Density")]
        [TestCase(1e5f, -1f, "material.Density")]
        public void Non_positive_modulus_or_density_is_rejected(float e, float density, string field)
        {
            var m = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, e, 0.3f, density);
            var ex = Assert.Throws<ArgumentException>(() => m.Validate());
            Assert.That(ex!.ParamName, Is.EqualTo(field));
        }

        [Test]
        public void Classic_model_needs_a_positive_lambda()
        {
            var m = new NeoHookeanMaterial(MaterialModel.NeoHookean, 1e5f, -0.2f, 1000f);
            var ex = Assert.Throws<ArgumentException>(() => m.Validate());
            Assert.That(ex!.ParamName, Is.EqualTo("material.PoissonRatio"));
            Assert.DoesNotThrow(() => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, -0.2f, 1000f).Validate());
        }
    }
}
