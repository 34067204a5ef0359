using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Read-only measurements of a soft body: per-element J and energy, totals, elastic
    /// forces (minus the energy gradient), strain colours. Everything in the mesh's element order.
    /// </summary>
    internal static class SoftBodyMeasures
    {
        public static SoftBodyStats Stats(SoftBody body)
        {
            var s = new SoftBodyStats { MinJ = float.PositiveInfinity, RestVolume = body.RestMeasure };
            Vector3 weighted = Vector3.Zero;
            float mass = 0;
            for (int i = 0; i < body.X.Length; i++)
            {
                float m = body.M[i];
                weighted += m * body.X[i];
                mass += m;
                s.KineticEnergy += 0.5f * m * body.V[i].LengthSquared();
                s.Momentum += m * body.V[i];
            }
            s.Centroid = weighted / mass;
            for (int e = 0; e < body.Tets.Length; e++)
            {
                ref TetElement t = ref body.Tets[e];
                Mat3 f = Gradient(body, e);
                float j = f.Determinant;
                // Plastic flow keeps det Fp = 1, so J of the elastic F is also the true volume ratio.
                s.Volume += j * t.RestVolume;
                s.MinJ = MathF.Min(s.MinJ, j);
                s.StrainEnergy += t.RestVolume * EnergyDensity(body, f);
            }
            for (int e = 0; e < body.Tris.Length; e++)
            {
                Membrane(body, e, out Vector3 f0, out Vector3 f1);
                float j = Vector3.Cross(f0, f1).Length();
                s.Volume += j * body.Tris[e].RestArea;
                s.MinJ = MathF.Min(s.MinJ, j);
                s.StrainEnergy += body.Tris[e].RestArea * body.Thickness * body.MembraneModel.EnergyDensity(f0, f1);
            }
            s.StrainEnergy += BendingEnergy(body);
            s.VolumeRatio = s.Volume / s.RestVolume;
            return s;
        }

        public static Mat3 Gradient(SoftBody body, int e)
        {
            ref TetElement t = ref body.Tets[e];
            return DeformationGradient.Of(body.X[t.A], body.X[t.B], body.X[t.C], body.X[t.D], t.RestInverse);
        }

        public static void Membrane(SoftBody body, int e, out Vector3 f0, out Vector3 f1)
        {
            ref TriangleElement t = ref body.Tris[e];
            t.Deformation(body.X[t.A], body.X[t.B], body.X[t.C], out f0, out f1);
        }

        public static float EnergyDensity(SoftBody body, in Mat3 f) =>
            body.Material.Model == MaterialModel.NeoHookean ? body.ClassicModel.EnergyDensity(f) : body.StableModel.EnergyDensity(f);

        public static Mat3 Stress(SoftBody body, in Mat3 f) =>
            body.Material.Model == MaterialModel.NeoHookean ? body.ClassicModel.FirstPiolaStress(f) : body.StableModel.FirstPiolaStress(f);

        static float BendingEnergy(SoftBody body)
        {
            float energy = 0;
            foreach (BendElement b in body.Bends)
            {
                float c = DihedralAngle.Of(body.X[b.A], body.X[b.B], body.X[b.C], body.X[b.D]) - b.RestAngle;
                if (c > MathF.PI) c -= 2f * MathF.PI;
                else if (c <= -MathF.PI) c += 2f * MathF.PI;
                energy += 0.5f * c * c / b.Compliance;
            }
            return energy;
        }

        /// <summary>J of each element, in mesh order (tets, or triangles for a shell).</summary>
        public static void ElementJ(SoftBody body, Span<float> into)
        {
            if (body.Tets.Length > 0)
            {
                CheckLength(into.Length, body.Tets.Length);
                for (int m = 0; m < body.Tets.Length; m++) into[m] = Gradient(body, body.TetOfMeshTet[m]).Determinant;
            }
            else
            {
                CheckLength(into.Length, body.Tris.Length);
                for (int m = 0; m < body.Tris.Length; m++)
                {
                    Membrane(body, body.TriOfMeshTri[m], out Vector3 f0, out Vector3 f1);
                    into[m] = Vector3.Cross(f0, f1).Length();
                }
            }
        }

        /// <summary>Strain energy of each element, J, in mesh order (membrane only for a shell).</summary>
        public static void ElementEnergy(SoftBody body, Span<float> into)
        {
            if (body.Tets.Length > 0)
            {
                CheckLength(into.Length, body.Tets.Length);
                for (int m = 0; m < body.Tets.Length; m++)
                {
                    int e = body.TetOfMeshTet[m];
                    into[m] = body.Tets[e].RestVolume * EnergyDensity(body, Gradient(body, e));
                }
            }
            else
            {
                CheckLength(into.Length, body.Tris.Length);
                for (int m = 0; m < body.Tris.Length; m++)
                {
                    int e = body.TriOfMeshTri[m];
                    Membrane(body, e, out Vector3 f0, out Vector3 f1);
                    into[m] = body.Tris[e].RestArea * body.Thickness * body.MembraneModel.EnergyDensity(f0, f1);
                }
            }
        }

        /// <summary>
        /// Elastic forces on the vertices, N: f = -dE/dx, assembled from each tet's first
        /// Piola-Kirchhoff stress as f_k = -V P Dm^-T (columns k = 1..3), f_0 = -(f_1 + f_2 + f_3).
        /// Tets only; a shell's membrane and bending forces are not included.
        /// </summary>
        public static void ElasticForces(SoftBody body, Span<Vector3> into)
        {
            CheckLength(into.Length, body.X.Length);
            into.Clear();
            for (int e = 0; e < body.Tets.Length; e++)
            {
                ref TetElement t = ref body.Tets[e];
                Mat3 p = Stress(body, Gradient(body, e)) * (-t.RestVolume);
                DeformationGradient.VertexGradients(p, t.RestInverse, out Vector3 g0, out Vector3 g1, out Vector3 g2, out Vector3 g3);
                into[t.A] += g0;
                into[t.B] += g1;
                into[t.C] += g2;
                into[t.D] += g3;
            }
        }

        /// <summary>
        /// Debug-draw colours per vertex: the average over its elements of the equivalent strain
        /// sqrt(2 Psi / E) (the strain a uniaxial bar would need to store that energy), mapped
        /// from blue (0) through green to red (at <paramref name="fullScale"/> and above).
        /// </summary>
        public static void StrainColors(SoftBody body, Span<Vector3> into, float fullScale, float[] scratch)
        {
            CheckLength(into.Length, body.X.Length);
            int n = body.X.Length;
            Array.Clear(scratch, 0, 2 * n);
            float e = body.Material.YoungsModulus;
            for (int k = 0; k < body.Tets.Length; k++)
            {
                ref TetElement t = ref body.Tets[k];
                float strain = MathF.Sqrt(MathF.Max(0f, 2f * EnergyDensity(body, Gradient(body, k)) / e));
                Accumulate(scratch, n, t.A, strain); Accumulate(scratch, n, t.B, strain);
                Accumulate(scratch, n, t.C, strain); Accumulate(scratch, n, t.D, strain);
            }
            for (int k = 0; k < body.Tris.Length; k++)
            {
                ref TriangleElement t = ref body.Tris[k];
                Membrane(body, k, out Vector3 f0, out Vector3 f1);
                float strain = MathF.Sqrt(MathF.Max(0f, 2f * body.MembraneModel.EnergyDensity(f0, f1) / e));
                Accumulate(scratch, n, t.A, strain); Accumulate(scratch, n, t.B, strain); Accumulate(scratch, n, t.C, strain);
            }
            for (int i = 0; i < n; i++) into[i] = Ramp(scratch[n + i] > 0 ? scratch[i] / scratch[n + i] / fullScale : 0f);
        }

        static void Accumulate(float[] scratch, int n, int v, float strain)
        {
            scratch[v] += strain;
            scratch[n + v] += 1f;
        }

        /// <summary>Blue (0) to green (0.5) to red (1), clamped.</summary>
        public static Vector3 Ramp(float s)
        {
            s = Math.Clamp(s, 0f, 1f);
            return s < 0.5f ? new Vector3(0, 2 * s, 1 - 2 * s) : new Vector3(2 * s - 1, 2 - 2 * s, 0);
        }

        static void CheckLength(int length, int needed)
        {
            if (length < needed) throw new ArgumentException($"the span must hold {needed} values, got {length}.", "into");
        }
    }
}
