using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Projects a range of tets (one colour, or part of one) with XPBD (Macklin, Mueller,
    /// Chentanez 2016), using the two-constraint form of the energy (Macklin and Mueller 2021).
    /// Per tet the two constraints are solved together as a 2x2 system: solved one after the
    /// other they would disagree at rest (each pulls against a non-zero rest value), and a body
    /// at rest would creep; solved together the rest state is an exact fixed point.
    /// </summary>
    internal static class XpbdTetSolver
    {
        /// <summary>
        /// One Gauss-Seidel pass over tets [start, end). <paramref name="gamma"/> is the XPBD
        /// damping factor (damping time / h): rows get (1 + gamma) on their stiffness part and
        /// -gamma grad C . (x - x_prev) on the right-hand side (Macklin et al. 2016, eq. 26).
        /// </summary>
        public static void Solve<TModel>(in TModel model, TetElement[] tets, Vector2[] lambdas, Vector3[] x, Vector3[] xPrev,
            float[] w, int start, int end, float h, float gamma)
            where TModel : struct, IHyperelasticModel
        {
            float invH2 = 1f / (h * h);
            // Compliance per unit volume over h^2; divided by each tet's rest volume below.
            float alphaDev = invH2 / model.DeviatoricStiffness;
            float alphaVol = invH2 / model.HydrostaticStiffness;
            float s = 1f + gamma;
            for (int e = start; e < end; e++)
            {
                ref TetElement t = ref tets[e];
                float w0 = w[t.A], w1 = w[t.B], w2 = w[t.C], w3 = w[t.D];
                if (w0 + w1 + w2 + w3 == 0f) continue;
                Vector3 x0 = x[t.A], x1 = x[t.B], x2 = x[t.C], x3 = x[t.D];
                Mat3 f = DeformationGradient.Of(x0, x1, x2, x3, t.RestInverse);
                model.Constraints(f, out float cD, out Mat3 dD, out float cH, out Mat3 dH);
                DeformationGradient.VertexGradients(dD, t.RestInverse, out Vector3 d0, out Vector3 d1, out Vector3 d2, out Vector3 d3);
                DeformationGradient.VertexGradients(dH, t.RestInverse, out Vector3 h0, out Vector3 h1, out Vector3 h2, out Vector3 h3);

                float kDD = w0 * d0.LengthSquared() + w1 * d1.LengthSquared() + w2 * d2.LengthSquared() + w3 * d3.LengthSquared();
                float kHH = w0 * h0.LengthSquared() + w1 * h1.LengthSquared() + w2 * h2.LengthSquared() + w3 * h3.LengthSquared();
                float kDH = w0 * Vector3.Dot(d0, h0) + w1 * Vector3.Dot(d1, h1) + w2 * Vector3.Dot(d2, h2) + w3 * Vector3.Dot(d3, h3);
                float invV = 1f / t.RestVolume;
                float aD = alphaDev * invV, aH = alphaVol * invV;
                ref Vector2 lambda = ref lambdas[e];
                float rD = -cD - aD * lambda.X;
                float rH = -cH - aH * lambda.Y;
                if (gamma > 0f)
                {
                    Vector3 v0 = x0 - xPrev[t.A], v1 = x1 - xPrev[t.B], v2 = x2 - xPrev[t.C], v3 = x3 - xPrev[t.D];
                    rD -= gamma * (Vector3.Dot(d0, v0) + Vector3.Dot(d1, v1) + Vector3.Dot(d2, v2) + Vector3.Dot(d3, v3));
                    rH -= gamma * (Vector3.Dot(h0, v0) + Vector3.Dot(h1, v1) + Vector3.Dot(h2, v2) + Vector3.Dot(h3, v3));
                }
                if (!XpbdConstraintPair.Solve(s * kDD + aD, s * kDH, s * kHH + aH, rD, rH, out float dlD, out float dlH)) continue;
                lambda.X += dlD;
                lambda.Y += dlH;
                x[t.A] = x0 + w0 * (dlD * d0 + dlH * h0);
                x[t.B] = x1 + w1 * (dlD * d1 + dlH * h1);
                x[t.C] = x2 + w2 * (dlD * d2 + dlH * h2);
                x[t.D] = x3 + w3 * (dlD * d3 + dlH * h3);
            }
        }
    }
}
