using System;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class MomentumTests
    {
        // stretched-block.json's block (0.6 x 0.2 x 0.2 m, 24 kg, E = 1e5 Pa, nu = 0.45), at the origin
        // where float positions are finest (the momentum tolerances below are near float noise).
        static SoftBody Block(World world, Mat3 deformation)
        {
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.6f, 0.2f, 0.2f), 6, 2, 2),
                new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, 0.45f, 1000f), Vector3.Zero);
            def.InitialDeformation = deformation;
            return world.GetSoftBody(world.CreateSoftBody(def));
        }

        static Vector3 AngularMomentum(SoftBody body)
        {
            Vector3 c = body.ComputeStats().Centroid, l = Vector3.Zero;
            for (int i = 0; i < body.VertexCount; i++) l += body.Masses[i] * Vector3.Cross(body.Positions[i] - c, body.Velocities[i]);
            return l;
        }

        [Test]
        public void Block_released_from_3x_stretch_gains_no_linear_or_angular_momentum()
        {
            World world = SoftBodyScenes.ZeroGravityWorld();
            SoftBody body = Block(world, Mat3.Diagonal(new Vector3(3, 1, 1)));
            float maxL = 0, maxP = 0, maxSpeed = 0;
            for (int i = 0; i < 60; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                maxL = MathF.Max(maxL, AngularMomentum(body).Length());
                maxP = MathF.Max(maxP, body.ComputeStats().Momentum.Length());
                foreach (Vector3 v in body.Velocities) maxSpeed = MathF.Max(maxSpeed, v.Length());
            }
            // The snap-back moves vertices at up to ~20 m/s, so m v r is ~100 kg m^2/s; before the
            // torque-free projection one Gauss-Seidel sweep created 1.45 kg m^2/s in the first step.
            TestContext.Out.WriteLine($"max |L| {maxL:E2} kg m^2/s, max |P| {maxP:E2} kg m/s, max vertex speed {maxSpeed:F1} m/s");
            Assert.That(maxL, Is.LessThan(0.01f));
            Assert.That(maxP, Is.LessThan(0.01f));
        }

        [Test]
        public void Stretched_block_tumbling_about_an_oblique_axis_keeps_its_angular_momentum()
        {
            World world = SoftBodyScenes.ZeroGravityWorld();
            SoftBody body = Block(world, Mat3.Diagonal(new Vector3(2, 1, 1)));
            var omega = new Vector3(1f, 2f, 3f);
            Vector3 c = body.ComputeStats().Centroid;
            for (int i = 0; i < body.VertexCount; i++) body.SetVertexVelocity(i, Vector3.Cross(omega, body.Positions[i] - c));
            Vector3 l0 = AngularMomentum(body);
            float worst = 0;
            for (int i = 0; i < 120; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                worst = MathF.Max(worst, (AngularMomentum(body) - l0).Length());
            }
            SoftBodyStats s = body.ComputeStats();
            TestContext.Out.WriteLine($"|L0| {l0.Length():F3} kg m^2/s, worst change {worst:E2}, |P| {s.Momentum.Length():E2}, energy left {s.KineticEnergy + s.StrainEnergy:F1} J");
            Assert.That(worst, Is.LessThan(1e-3f * l0.Length()));
            Assert.That(s.Momentum.Length(), Is.LessThan(0.01f));
        }
    }
}
