using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Multiplicative plasticity F = Fe Fp on tets, with Fp kept inside the rest inverse
    /// (Dm^-1 Fp^-1). The elastic stretch is measured by its logarithmic (Hencky) strain:
    /// eigen-decompose Fe^T Fe = V diag(s_i^2) V^T, e_i = ln s_i, dev e = e - mean(e). Above the
    /// yield strain a fraction (flow rate x dt, at most 1) of the excess flows into Fp:
    /// Fp' = V diag(exp(de)) V^T Fp with de along dev e, so the rest inverse becomes
    /// Dm^-1 Fp^-1 V diag(exp(-de)) V^T. The flow is traceless, so det Fp stays 1 and the rest
    /// volume, masses and compliances do not change. Inverted or nearly collapsed elements do
    /// not flow (their strain has no meaningful logarithm).
    /// </summary>
    internal static class PlasticFlow
    {
        public static void Apply(SoftBody body, float dt)
        {
            SoftPlasticity p = body.Plasticity;
            float fraction = MathF.Min(1f, p.FlowRate * dt);
            Vector3[] x = body.X;
            TetElement[] tets = body.Tets;
            float[] accumulated = body.PlasticStrain;
            for (int e = 0; e < tets.Length; e++)
            {
                ref TetElement t = ref tets[e];
                Mat3 f = DeformationGradient.Of(x[t.A], x[t.B], x[t.C], x[t.D], t.RestInverse);
                if (!(f.Determinant > 0.05f)) continue;
                Vector3 s2 = Rotation.Diagonalize(f.Transposed * f, out Quaternion axes);
                if (!(s2.X > 0 && s2.Y > 0 && s2.Z > 0)) continue;
                Vector3 strain = 0.5f * new Vector3(MathF.Log(s2.X), MathF.Log(s2.Y), MathF.Log(s2.Z));
                Vector3 dev = strain - new Vector3((strain.X + strain.Y + strain.Z) / 3f);
                float norm = dev.Length();
                if (!(norm > p.YieldStrain)) continue;
                float flow = fraction * (norm - p.YieldStrain);
                flow = MathF.Min(flow, p.MaxStrain - accumulated[e]);
                if (!(flow > 0)) continue;
                accumulated[e] += flow;
                Vector3 step = dev * (flow / norm);
                Mat3 v = Mat3.FromQuaternion(axes);
                Mat3 shrink = Mat3.RotateDiagonal(v, new Vector3(MathF.Exp(-step.X), MathF.Exp(-step.Y), MathF.Exp(-step.Z)));
                t.RestInverse = t.RestInverse * shrink;
            }
        }
    }
}
