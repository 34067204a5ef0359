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
        /// One Gauss-Seidel pass over tets [start, end). Undamped: damping is a velocity pass
        /// after the substep (<see cref="RayleighDamping"/>). Each correction is made free of
        /// net angular impulse (<see cref="TorqueFree"/>) unless the tet has a pinned or attached vertex.
        /// <paramref name="keep"/>, when not null, receives each tet's gradients for the damping pass.
        /// </summary>
        public static void Solve<TModel>(in TModel model, TetElement[] tets, Vector2[] lambdas, TetGradients[]? keep, Vector3[] x, Vector3[] xPrev,
            float[] w, float[] m, float[] free, int start, int end, float h)
            where TModel : struct, IHyperelasticModel
        {
            float invH2 = 1f / (h * h);
            // Compliance per unit volume over h^2; divided by each tet's rest volume below.
            float alphaDev = invH2 / model.DeviatoricStiffness;
            float alphaVol = invH2 / model.HydrostaticStiffness;
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
                if (keep != null)
                {
                    keep[e] = new TetGradients { D0 = d0, D1 = d1, D2 = d2, D3 = d3, H0 = h0, H1 = h1, H2 = h2, H3 = h3, KDD = kDD, KDH = kDH, KHH = kHH };
                }
                float invV = 1f / t.RestVolume;
                float aD = alphaDev * invV, aH = alphaVol * invV;
                ref Vector2 lambda = ref lambdas[e];
                float rD = -cD - aD * lambda.X;
                float rH = -cH - aH * lambda.Y;
                if (!XpbdConstraintPair.Solve(kDD + aD, kDH, kHH + aH, rD, rH, out float dlD, out float dlH)) continue;
                lambda.X += dlD;
                lambda.Y += dlH;
                Vector3 g0 = dlD * d0 + dlH * h0, g1 = dlD * d1 + dlH * h1, g2 = dlD * d2 + dlH * h2, g3 = dlD * d3 + dlH * h3;
                if (free[t.A] > 0f && free[t.B] > 0f && free[t.C] > 0f && free[t.D] > 0f)
                    TorqueFree.Project(xPrev[t.A], xPrev[t.B], xPrev[t.C], xPrev[t.D], m[t.A], m[t.B], m[t.C], m[t.D], ref g0, ref g1, ref g2, ref g3);
                x[t.A] = x0 + w0 * g0;
                x[t.B] = x1 + w1 * g1;
                x[t.C] = x2 + w2 * g2;
                x[t.D] = x3 + w3 * g3;
            }
        }
    }
}
