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

        [TestCase(1e9f, 0.5f, 1, 0)]
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
            def.Substeps = substeps;
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
