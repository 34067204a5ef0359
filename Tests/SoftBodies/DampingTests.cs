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
            // Amplitude decay rate of the breathing mode (peaks of the volume ratio over 1 s).
        static float DecayRate(float dt, int substeps, float dampingTime, out float omega)
        {
            World world = SoftBodyScenes.ZeroGravityWorld();
            SoftBodyDef def = SoftBodyScenes.Cube(0.4f, 3, new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e4f, 0.3f, 1000f), Vector3.Zero);
            def.InitialDeformation = Mat3.Diagonal(new Vector3(1.05f));
            def.DampingTime = dampingTime;
            def.Substeps = substeps;
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            int steps = (int)MathF.Round(1f / dt), peaks = 0;
            float before = 0f, last = body.ComputeStats().VolumeRatio - 1f, firstT = 0f, firstA = 0f, lastT = 0f, lastA = 0f;
            for (int i = 1; i <= steps; i++)
            {
                world.Step(dt);
                float y = body.ComputeStats().VolumeRatio - 1f;
                if (i >= 2 && last > before && last >= y && last > 0f)
                {
                    if (peaks++ == 0) { firstT = (i - 1) * dt; firstA = last; }
                    lastT = (i - 1) * dt;
                    lastA = last;
                }
                before = last;
                last = y;
            }
            Assert.That(peaks, Is.GreaterThanOrEqualTo(4), "the breathing mode rings");
            omega = 2f * MathF.PI * (peaks - 1) / (lastT - firstT);
            return MathF.Log(firstA / lastA) / (lastT - firstT);
        }

        // The rate the damping adds (damped minus undamped, so that XPBD's own h-dependent
        // dissipation cancels) must be the dashpot's tau w^2 / 2 at any step and substep count.
        [Test]
        public void Damping_decay_rate_is_the_same_at_1_1200_and_1_2400_s_substeps()
        {
            const float tau = 2e-3f;
            float a = DecayRate(1f / 120f, 10, tau, out float omega) - DecayRate(1f / 120f, 10, 0f, out _);
            float b = DecayRate(1f / 60f, 40, tau, out _) - DecayRate(1f / 60f, 40, 0f, out _);
            float expected = 0.5f * tau * omega * omega;
            TestContext.Out.WriteLine($"breathing mode w = {omega:F1} rad/s; damping adds {a:F3} /s at h = 1/1200 s, {b:F3} /s at h = 1/2400 s; tau w^2 / 2 = {expected:F3} /s");
            Assert.That(b, Is.EqualTo(a).Within(0.05f * a));
            Assert.That(a, Is.EqualTo(expected).Within(0.2f * expected));
        }

        // pinned-flag.json through the API: a thin one-layer tet sheet swinging from a hinge line.
        static float WorstEnergyRise(float dampingTime, int substeps, out float excess)
        {
            var world = new World();
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(1f, 0.02f, 0.6f), 10, 1, 6),
                new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, 0.3f, 200f), new Vector3(0, 2, 0));
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-0.5f, 0.01f, -0.3f), new Vector3(-0.5f, 0.01f, 0.3f)) };
            def.DampingTime = dampingTime;
            def.Substeps = substeps;
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            float g = 9.81f;
            float Total()
            {
                SoftBodyStats s = body.ComputeStats();
                return s.KineticEnergy + s.StrainEnergy + body.TotalMass * g * s.Centroid.Y;
            }
            float start = Total(), lowest = start, rise = 0f;
            excess = 0f;
            for (int i = 0; i < 180; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                float e = Total();
                rise = MathF.Max(rise, e - lowest);
                lowest = MathF.Min(lowest, e);
                excess = MathF.Max(excess, e - start);
            }
            return rise;
        }

        [Test]
        public void Damping_never_adds_energy_to_a_swinging_thin_sheet()
        {
            // 40 substeps: the elastic solve itself is then energy-stable, so any rise is the damping's.
            float rise = WorstEnergyRise(0.01f, 40, out float excess);
            // Default substeps: XPBD's unconverged sheet shows a small transient excess of its own;
            // the damping must not add to it (the eq. 26 damping it replaced raised 0.2 J to 3.8 J).
            WorstEnergyRise(0f, 0, out float undamped);
            WorstEnergyRise(0.01f, 0, out float damped);
            TestContext.Out.WriteLine($"40 substeps, tau 0.01 s: largest rise of total energy {rise:F4} J, largest excess over the start {excess:F4} J (m g L/2 = 11.8 J); 10 substeps: excess {undamped:F3} J undamped, {damped:F3} J damped");
            Assert.That(rise, Is.LessThan(0.01f));
            Assert.That(damped, Is.LessThanOrEqualTo(undamped + 0.01f));
        }
    }
}
