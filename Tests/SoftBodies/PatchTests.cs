using System;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// The patch test: every vertex of a mesh moved by one affine map x = A X + b. Every linear
    /// tet then has F = A exactly, so the stress is the closed form P(A) everywhere, the
    /// internal forces cancel at interior vertices, and the nodal forces carry the stress:
    /// since E(x) = V Psi(A) and dE/dA = sum_i (dE/dx_i) X_i^T, sum_i f_i X_i^T = -V P(A).
    /// </summary>
    public class PatchTests
    {
        static readonly Mat3 A = Mat3.FromRows(new Vector3(1.20f, 0.10f, 0.00f), new Vector3(0.05f, 0.90f, 0.10f), new Vector3(0.00f, 0.15f, 1.10f));
        static readonly Vector3 Offset = new Vector3(0.3f, -0.2f, 0.5f);

        static Mat3 ClosedFormStress(MaterialModel model, float e, float nu)
        {
            // Written from the textbook formulas, independently of the energy structs.
            float mu = e / (2 * (1 + nu)), lambda = e * nu / ((1 + nu) * (1 - 2 * nu));
            float j = A.Determinant;
            Mat3 invT = A.Inverse().Transposed;
            if (model == MaterialModel.NeoHookean) return (A - invT) * mu + invT * (lambda * MathF.Log(j));
            float ms = 4f / 3f * mu, ls = lambda + 5f / 6f * mu, alpha = 1 + 0.75f * ms / ls;
            float ic = A.FrobeniusSquared;
            return A * (ms * (1 - 1 / (ic + 1))) + invT * (ls * (j - alpha) * j);
        }

        [Test]
        public void Uniform_deformation_gives_closed_form_stress_and_no_interior_force([Values] MaterialModel model, [Values] TetSplit split)
        {
            const float e = 1000f, nu = 0.3f;
            var world = SoftBodyScenes.ZeroGravityWorld();
            SoftMesh mesh = SoftMesh.Box(new Vector3(1f, 0.8f, 1.2f), 3, 3, 3, split);
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(SoftBodyDef.Of(mesh, new NeoHookeanMaterial(model, e, nu, 1000f), Vector3.Zero)));
            ReadOnlySpan<Vector3> rest = mesh.Vertices;
            for (int i = 0; i < rest.Length; i++) body.SetVertexPosition(i, A * rest[i] + Offset);

            var j = new float[body.ElementCount];
            body.ComputeElementJ(j);
            foreach (float v in j) Assert.That(v, Is.EqualTo(A.Determinant).Within(1e-5f));

            var forces = new Vector3[body.VertexCount];
            body.ComputeElasticForces(forces);
            Mat3 p = ClosedFormStress(model, e, nu);
            float scale = MathF.Sqrt(p.FrobeniusSquared) * 0.96f / 27f; // stress times one cell's volume
            Mat3 moment = Mat3.Zero;
            Vector3 total = Vector3.Zero;
            Vector3 half = 0.5f * new Vector3(1f, 0.8f, 1.2f);
            for (int i = 0; i < rest.Length; i++)
            {
                moment += Mat3.Outer(forces[i], rest[i]);
                total += forces[i];
                Vector3 q = Vector3.Abs(rest[i]) - half;
                bool interior = q.X < -1e-4f && q.Y < -1e-4f && q.Z < -1e-4f;
                if (interior) Assert.That(forces[i].Length(), Is.LessThan(1e-4f * scale), $"interior vertex {i}");
            }
            Assert.That(total.Length(), Is.LessThan(1e-4f * scale), "net force");
            Mat3 expected = p * (-0.96f);
            Assert.That(MathF.Sqrt((moment - expected).FrobeniusSquared), Is.LessThan(1e-4f * MathF.Sqrt(expected.FrobeniusSquared)), "sum f X^T = -V P(A)");

            Mat3 energyStress = model == MaterialModel.NeoHookean
                ? NeoHookeanEnergy.Of(body.Material).FirstPiolaStress(A)
                : StableNeoHookeanEnergy.Of(body.Material).FirstPiolaStress(A);
            Assert.That(MathF.Sqrt((energyStress - p).FrobeniusSquared), Is.LessThan(1e-5f * MathF.Sqrt(p.FrobeniusSquared)), "P(A)");
            Assert.That(body.ComputeStats().StrainEnergy, Is.EqualTo(0.96f * SoftBodyMeasuresEnergy(body, A)).Within(1e-4f * 0.96f * SoftBodyMeasuresEnergy(body, A)));
        }

        static float SoftBodyMeasuresEnergy(SoftBody body, in Mat3 f) =>
            body.Material.Model == MaterialModel.NeoHookean ? NeoHookeanEnergy.Of(body.Material).EnergyDensity(f) : StableNeoHookeanEnergy.Of(body.Material).EnergyDensity(f);
    }
}
