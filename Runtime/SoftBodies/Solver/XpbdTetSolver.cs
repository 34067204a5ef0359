using System;
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
        /// A tet that was near the <see cref="VolumeFloor"/> is then held above it.
        /// With <paramref name="keep"/> each tet's gradients are stored in the stream for the damping pass.
        /// </summary>
        public static void Solve<TModel>(in TModel model, TetStream tets, Vector2[] lambdas, bool keep, Vector3[] x, Vector3[] xPrev,
            float[] w, float[] m, float[] free, int start, int end, float h)
            where TModel : struct, IHyperelasticModel
        {
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            float invH2 = 1f / (h * h);
            // Compliance per unit volume over h^2; divided by each tet's rest volume below.
            float alphaDev = invH2 / model.DeviatoricStiffness;
            float alphaVol = invH2 / model.HydrostaticStiffness;
            for (int e = start; e < end; e++)
            {
                int a = vertices[e], b = vertices[n + e], c = vertices[2 * n + e], d = vertices[3 * n + e];
                float w0 = w[a], w1 = w[b], w2 = w[c], w3 = w[d];
                if (w0 + w1 + w2 + w3 == 0f) continue;
                Vector3 x0 = x[a], x1 = x[b], x2 = x[c], x3 = x[d];
                Mat3 restInverse = RestInverse(tets, e);
                Mat3 f = DeformationGradient.Of(x0, x1, x2, x3, restInverse);
                model.Constraints(f, out float cD, out Mat3 dD, out float cH, out Mat3 dH);
                // J - 1 as the wide kernel has it (the stable model's C_H), so both take the same
                // tets; the floor holds only a body something presses.
                bool nearFloor = tets.Loaded
                    && (typeof(TModel) == typeof(StableNeoHookeanEnergy) ? cH : (float)(StableNeoHookeanEnergy.Determinant(f) - 1.0)) < VolumeFloor.Trigger - 1f;
                DeformationGradient.VertexGradients(dD, restInverse, out Vector3 d0, out Vector3 d1, out Vector3 d2, out Vector3 d3);
                DeformationGradient.VertexGradients(dH, restInverse, out Vector3 h0, out Vector3 h1, out Vector3 h2, out Vector3 h3);

                float kDD = w0 * d0.LengthSquared() + w1 * d1.LengthSquared() + w2 * d2.LengthSquared() + w3 * d3.LengthSquared();
                float kHH = w0 * h0.LengthSquared() + w1 * h1.LengthSquared() + w2 * h2.LengthSquared() + w3 * h3.LengthSquared();
                float kDH = w0 * Vector3.Dot(d0, h0) + w1 * Vector3.Dot(d1, h1) + w2 * Vector3.Dot(d2, h2) + w3 * Vector3.Dot(d3, h3);
                if (keep)
                {
                    tets.Set(0, e, d0);
                    tets.Set(3, e, d1);
                    tets.Set(6, e, d2);
                    tets.Set(9, e, d3);
                    tets.Set(12, e, h0);
                    tets.Set(15, e, h1);
                    tets.Set(18, e, h2);
                    tets.Set(21, e, h3);
                    tets.Gradients[24 * n + e] = kDD;
                    tets.Gradients[25 * n + e] = kDH;
                    tets.Gradients[26 * n + e] = kHH;
                }
                float invV = 1f / tets.RestVolume[e];
                float aD = alphaDev * invV, aH = alphaVol * invV;
                ref Vector2 lambda = ref lambdas[e];
                float rD = -cD - aD * lambda.X;
                float rH = -cH - aH * lambda.Y;
                if (!XpbdConstraintPair.Solve(kDD + aD, kDH, kHH + aH, rD, rH, out float dlD, out float dlH))
                {
                    if (nearFloor) VolumeFloor.Hold(tets, e, x);
                    continue;
                }
                Vector3 g0 = dlD * d0 + dlH * h0, g1 = dlD * d1 + dlH * h1, g2 = dlD * d2 + dlH * h2, g3 = dlD * d3 + dlH * h3;
                if (typeof(TModel) != typeof(StableNeoHookeanEnergy) && LimitReach(tets.RestVolume[e], w0 * g0, w1 * g1, w2 * g2, w3 * g3, ref dlD, ref dlH))
                {
                    g0 = dlD * d0 + dlH * h0; g1 = dlD * d1 + dlH * h1; g2 = dlD * d2 + dlH * h2; g3 = dlD * d3 + dlH * h3;
                }
                lambda.X += dlD;
                lambda.Y += dlH;
                TorqueFree.ProjectIfFree(a, b, c, d, xPrev, m, free, ref g0, ref g1, ref g2, ref g3);
                x[a] = x0 + w0 * g0;
                x[b] = x1 + w1 * g1;
                x[c] = x2 + w2 * g2;
                x[d] = x3 + w3 * g3;
                if (nearFloor) VolumeFloor.Hold(tets, e, x);
            }
        }

        /// <summary>
        /// The classic energy's trust region (true when it scaled the multipliers' update down,
        /// from the vertices' moves <paramref name="move0"/>..<paramref name="move3"/>): the tet's correction is scaled down so that no
        /// vertex moves further than half the tet's size, cbrt(6 V_rest) (the cell edge of a
        /// box mesh). Below J = <see cref="NeoHookeanEnergy.MinJ"/> its ln J is continued by a
        /// line of slope 1 / MinJ, and a tet crushed there (or inverted) gets deviatoric and
        /// volume constraints of tens to hundreds with nearly parallel gradients; their
        /// linearised projection moved vertices 0.7-5 m on a 5 cm tet, which crushed the
        /// neighbours in turn: a 7 kg box (0.19 x 0.16 x 0.24 m, one row of five cells) at
        /// E &gt;= 3.5e8 Pa dropped 1.3 m onto the ground went from min J 0.35 to NaN within four
        /// substeps (soft fuzz seed 639). The stable energy's constraints stay moderate there (J - 1
        /// and sqrt(I_C - 3)), and it is left exactly as it was (its wide kernels match).
        /// </summary>
        static bool LimitReach(float restVolume, Vector3 move0, Vector3 move1, Vector3 move2, Vector3 move3, ref float dlD, ref float dlH)
        {
            float most = MathF.Sqrt(MathF.Max(MathF.Max(move0.LengthSquared(), move1.LengthSquared()), MathF.Max(move2.LengthSquared(), move3.LengthSquared())));
            float reach = 0.5f * MathF.Cbrt(6f * restVolume);
            if (!(most > reach)) return false;
            float scale = reach / most;
            dlD *= scale;
            dlH *= scale;
            return true;
        }

        /// <summary>Dm^-1 of element <paramref name="e"/> from the stream's columns.</summary>
        public static Mat3 RestInverse(TetStream tets, int e)
        {
            int n = tets.Count;
            float[] r = tets.RestInverse;
            return new Mat3(new Vector3(r[e], r[n + e], r[2 * n + e]), new Vector3(r[3 * n + e], r[4 * n + e], r[5 * n + e]),
                new Vector3(r[6 * n + e], r[7 * n + e], r[8 * n + e]));
        }
    }
}
