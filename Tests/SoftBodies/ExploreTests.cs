using System;
using System.Numerics;
using Fulcrum;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    [Explicit]
    public class ExploreTests
    {
        [TestCase(1e9f, 0.98f, 0.45f)]
        [TestCase(1e9f, 0.9f, 0.45f)]
        [TestCase(1e5f, 0.98f, 0.45f)]
        [TestCase(1e9f, 1.02f, 0.45f)]
        public void Recover_from_scaling(float e, float scale, float nu)
        {
            World world = SoftBodyScenes.ZeroGravityWorld();
            var mat = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, e, nu, 1000f);
            var def = SoftBodyScenes.Cube(0.5f, 4, mat, new Vector3(0, 0.5f, 0));
            def.InitialDeformation = Fulcrum.Mathematics.Mat3.Diagonal(new Vector3(scale, scale * 1.01f, scale));
            SoftBodyHandle h = world.CreateSoftBody(def);
            SoftBody b = world.GetSoftBody(h);
            for (int i = 0; i < 120; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                if (i < 5 || i % 30 == 29)
                {
                    var s = b.ComputeStats();
                    TestContext.Out.WriteLine($"E={e:g} scale={scale} step {i + 1}: vol={s.VolumeRatio:F5} minJ={s.MinJ:F4} Es={s.StrainEnergy:g3} Ek={s.KineticEnergy:g3}");
                }
            }
        }

        [TestCase(0f)]
        [TestCase(1f)]
        public void Rest_drift(float offset)
        {
            World world = SoftBodyScenes.ZeroGravityWorld();
            var def = SoftBodyScenes.Cube(0.5f, 3, new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, 0.45f, 1000f), new Vector3(1, 2, 3) * offset);
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            Vector3[] start = body.Positions.ToArray();
            for (int i = 0; i < 120; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                if (i < 5 || i % 20 == 0) TestContext.Out.WriteLine($"off={offset} step {i}: disp {SoftBodyScenes.MaxDisplacement(body.Positions, start):g3} Ek {body.ComputeStats().KineticEnergy:g3} Es {body.ComputeStats().StrainEnergy:g3}");
            }
        }

        [TestCase(1e9f, 0)]
        [TestCase(1e7f, 0)]
        [TestCase(1e9f, 40)]
        public void Cantilever(float e, int substeps)
        {
            var world = new World();
            var mat = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, e, 0.3f, 1000f);
            var def = SoftBodyDef.Of(SoftMesh.Beam(1f, 0.1f, 10), mat, Vector3.Zero);
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-0.5f, -1, -1), new Vector3(-0.5f, 1, 1)) };
            def.Probes = new[] { new Vector3(0.5f, 0, 0) };
            def.Substeps = substeps;
            SoftBody b = world.GetSoftBody(world.CreateSoftBody(def));
            for (int i = 0; i < 180; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                if (i % 30 == 29)
                {
                    var s = b.ComputeStats();
                    TestContext.Out.WriteLine($"E={e:g} n={substeps} step {i + 1}: tip={b.GetProbe(0)} vol={s.VolumeRatio:F5} minJ={s.MinJ:F4} Es={s.StrainEnergy:g3} Ek={s.KineticEnergy:g3}");
                }
            }
            float q = 1000f * 9.81f * 0.01f, I = 1e-4f / 12f;
            TestContext.Out.WriteLine($"Euler-Bernoulli tip deflection {q / (8 * e * I):g4}");
        }

        [Test]
        public void Stuck_state()
        {
            World world = SoftBodyScenes.WorldWithGround(0, 0f);
            var mat = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e9f, 0.45f, 1000f);
            var def = SoftBodyScenes.Cube(0.5f, 2, mat, new Vector3(0, 0.5f, 0));
            def.Friction = 0;
            SoftBodyHandle h = world.CreateSoftBody(def);
            SoftBody b = world.GetSoftBody(h);
            for (int i = 0; i < 120; i++) world.Step(SoftBodyScenes.Dt);
            var s = b.ComputeStats();
            TestContext.Out.WriteLine($"vol={s.VolumeRatio:F5} minJ={s.MinJ:F4} Es={s.StrainEnergy:g3} Ek={s.KineticEnergy:g3}");
            var rest = b.Mesh.Vertices;
            for (int i = 0; i < b.VertexCount; i++) TestContext.Out.WriteLine($"v{i} rest={rest[i]} x={b.Positions[i]} d={b.Positions[i] - rest[i] - new Vector3(0, 0.255f, 0)}");
            var j = new float[b.ElementCount];
            b.ComputeElementJ(j);
            TestContext.Out.WriteLine(string.Join(" ", Array.ConvertAll(j, x => x.ToString("F4"))));
        }

        [TestCase(1e9f, 0.5f, 1, -1)]
        [TestCase(1e9f, 0.0f, 1, -1)]
        [TestCase(1e9f, 0.0f, 1, 0)]
        [TestCase(1e9f, 0.5f, 4, 0)]
        [TestCase(1e9f, 0.5f, 1, 40)]
        [TestCase(1e7f, 0.0f, 1, 0)]
        public void Stiff_drop(float e, float friction, int iterations, int substeps)
        {
            World world = SoftBodyScenes.WorldWithGround(0, friction);
            var mat = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, e, 0.45f, 1000f);
            var def = SoftBodyScenes.Cube(0.5f, 4, mat, new Vector3(0, 0.5f, 0));
            def.Friction = friction;
            def.Iterations = iterations;
            def.Substeps = Math.Max(0, substeps);
            SoftBodyHandle h = world.CreateSoftBody(def);
            SoftBody b = world.GetSoftBody(h);
            for (int i = 0; i < 180; i++)
            {
                world.Step(SoftBodyScenes.Dt);
                if (i % 60 == 59 || i == 30)
                {
                    var s = b.ComputeStats();
                    TestContext.Out.WriteLine($"E={e:g} mu={friction} it={iterations} step {i + 1}: c={s.Centroid} vol={s.VolumeRatio:F5} minJ={s.MinJ:F4} Es={s.StrainEnergy:g3} Ek={s.KineticEnergy:g3}");
                }
            }
        }
    }
}
