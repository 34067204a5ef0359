using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// XPBD projection of membrane triangles, the 2D counterpart of <see cref="XpbdTetSolver"/>:
    /// F = [x1 - x0, x2 - x0] Dm^-1 (3x2), two constraints solved together, compliances
    /// 1/(mu A t) and 1/(lambda A t) for rest area A and thickness t.
    /// </summary>
    internal static class XpbdMembraneSolver
    {
        /// <summary>One undamped Gauss-Seidel pass over triangles [start, end), torque-free like the tets' (<see cref="TorqueFree"/>).</summary>
        public static void Solve(in MembraneEnergy model, float thickness, TriangleElement[] tris, Vector2[] lambdas, Vector3[] x, Vector3[] xPrev,
            float[] w, float[] m, float[] free, int start, int end, float h)
        {
            float invH2 = 1f / (h * h);
            float alphaDev = invH2 / (model.Mu * thickness);
            float alphaVol = invH2 / (model.Lambda * thickness);
            for (int e = start; e < end; e++)
            {
                ref TriangleElement t = ref tris[e];
                float w0 = w[t.A], w1 = w[t.B], w2 = w[t.C];
                if (w0 + w1 + w2 == 0f) continue;
                Vector3 x0 = x[t.A], x1 = x[t.B], x2 = x[t.C];
                t.Deformation(x0, x1, x2, out Vector3 f0, out Vector3 f1);
                model.Constraints(f0, f1, out float cD, out Vector3 dD0, out Vector3 dD1, out float cH, out Vector3 dH0, out Vector3 dH1);
                t.VertexGradients(dD0, dD1, out Vector3 d0, out Vector3 d1, out Vector3 d2);
                t.VertexGradients(dH0, dH1, out Vector3 g0, out Vector3 g1, out Vector3 g2);
                float kDD = w0 * d0.LengthSquared() + w1 * d1.LengthSquared() + w2 * d2.LengthSquared();
                float kHH = w0 * g0.LengthSquared() + w1 * g1.LengthSquared() + w2 * g2.LengthSquared();
                float kDH = w0 * Vector3.Dot(d0, g0) + w1 * Vector3.Dot(d1, g1) + w2 * Vector3.Dot(d2, g2);
                float invA = 1f / t.RestArea;
                float aD = alphaDev * invA, aH = alphaVol * invA;
                ref Vector2 lambda = ref lambdas[e];
                float rD = -cD - aD * lambda.X;
                float rH = -cH - aH * lambda.Y;
                if (!XpbdConstraintPair.Solve(kDD + aD, kDH, kHH + aH, rD, rH, out float dlD, out float dlH)) continue;
                lambda.X += dlD;
                lambda.Y += dlH;
                Vector3 q0 = dlD * d0 + dlH * g0, q1 = dlD * d1 + dlH * g1, q2 = dlD * d2 + dlH * g2;
                TorqueFree.ProjectIfFree(t.A, t.B, t.C, xPrev, m, free, ref q0, ref q1, ref q2);
                x[t.A] = x0 + w0 * q0;
                x[t.B] = x1 + w1 * q1;
                x[t.C] = x2 + w2 * q2;
            }
        }
    }
}
