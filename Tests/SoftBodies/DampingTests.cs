using System;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class DampingTests
    {
        // A free cube released from a uniform 10% stretch rings in its breathing mode; the
        // energy left after 0.5 s must not depend on how the time is cut into steps and substeps.
        static float EnergyLeft(float dt, int substeps, float dampingTime)
        {
            World world = SoftBodyScenes.ZeroGravityWorld();
            SoftBodyDef def = SoftBodyScenes.Cube(0.4f, 3, new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e4f, 0.3f, 1000f), Vector3.Zero);
            def.InitialDeformation = Mat3.Diagonal(new Vector3(1.1f));
            def.DampingTime = dampingTime;
            def.Substeps = substeps;
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            float start = body.ComputeStats().StrainEnergy;
            int steps = (int)MathF.Round(0.5f / dt);
            for (int i = 0; i < steps; i++) world.Step(dt);
            SoftBodyStats s = body.ComputeStats();
            return (s.StrainEnergy + s.KineticEnergy) / start;
        }

        // XPBD itself dissipates (it is implicit Euler per substep, losing about (w h)^2 per
        // substep), and that part does depend on h. What the damping time adds must not: the
        // ratio of damped to undamped energy is compared at different substep lengths.
        [Test]
        public void Damping_does_not_depend_on_the_step_or_substep_size()
        {
            // Breathing mode w ~ pi c / L ~ 29 rad/s; the damping removes about exp(-w^2 tau t).
            const float tau = 2e-3f;
            float a = EnergyLeft(1f / 60f, 10, tau) / EnergyLeft(1f / 60f, 10, 0f);
            float b = EnergyLeft(1f / 120f, 10, tau) / EnergyLeft(1f / 120f, 10, 0f);
            float c = EnergyLeft(1f / 60f, 40, tau) / EnergyLeft(1f / 60f, 40, 0f);
            TestContext.Out.WriteLine($"damped / undamped energy after 0.5 s: h = 1/600 s {a:F4}, h = 1/1200 s {b:F4}, h = 1/2400 s {c:F4}");
            Assert.That(a, Is.LessThan(0.7f), "the damping acts");
            Assert.That(b, Is.EqualTo(a).Within(0.15f * a));
            Assert.That(c, Is.EqualTo(a).Within(0.15f * a));
        }
    }
}
