using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// XPBD projection of dihedral hinges: C = theta - theta_rest (wrapped into (-pi, pi]),
    /// compliance from the discrete-shell bending stiffness (see <see cref="ShellBuilder"/>).
    /// </summary>
    internal static class XpbdBendingSolver
    {
        public static void Solve(BendElement[] bends, float[] lambdas, Vector3[] x, Vector3[] xPrev, float[] w,
            int start, int end, float h, float gamma)
        {
            float invH2 = 1f / (h * h);
            float s = 1f + gamma;
            for (int e = start; e < end; e++)
            {
                ref BendElement b = ref bends[e];
                float wa = w[b.A], wb = w[b.B], wc = w[b.C], wd = w[b.D];
                if (wa + wb + wc + wd == 0f) continue;
                Vector3 xa = x[b.A], xb = x[b.B], xc = x[b.C], xd = x[b.D];
                if (!DihedralAngle.WithGradient(xa, xb, xc, xd, out float angle, out Vector3 ga, out Vector3 gb, out Vector3 gc, out Vector3 gd))
                    continue;
                float c = angle - b.RestAngle;
                if (c > MathF.PI) c -= 2f * MathF.PI;
                else if (c <= -MathF.PI) c += 2f * MathF.PI;
                float k = wa * ga.LengthSquared() + wb * gb.LengthSquared() + wc * gc.LengthSquared() + wd * gd.LengthSquared();
                float alpha = b.Compliance * invH2;
                float r = -c - alpha * lambdas[e];
                if (gamma > 0f)
                    r -= gamma * (Vector3.Dot(ga, xa - xPrev[b.A]) + Vector3.Dot(gb, xb - xPrev[b.B]) + Vector3.Dot(gc, xc - xPrev[b.C]) + Vector3.Dot(gd, xd - xPrev[b.D]));
                float denom = s * k + alpha;
                if (!(denom > 1e-30f)) continue;
                float dl = r / denom;
                lambdas[e] += dl;
                x[b.A] = xa + wa * dl * ga;
                x[b.B] = xb + wb * dl * gb;
                x[b.C] = xc + wc * dl * gc;
                x[b.D] = xd + wd * dl * gd;
            }
        }
    }
}
