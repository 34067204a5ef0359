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
        /// <summary>One undamped Gauss-Seidel pass over hinges [start, end), torque-free like the tets' (<see cref="TorqueFree"/>).</summary>
        public static void Solve(BendElement[] bends, float[] lambdas, Vector3[] x, Vector3[] xPrev, float[] w, float[] m, float[] free,
            int start, int end, float h)
        {
            float invH2 = 1f / (h * h);
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
                float denom = k + alpha;
                if (!(denom > 1e-30f)) continue;
                float dl = r / denom;
                lambdas[e] += dl;
                ga *= dl; gb *= dl; gc *= dl; gd *= dl;
                TorqueFree.ProjectIfFree(b.A, b.B, b.C, b.D, xPrev, m, free, ref ga, ref gb, ref gc, ref gd);
                x[b.A] = xa + wa * ga;
                x[b.B] = xb + wb * gb;
                x[b.C] = xc + wc * gc;
                x[b.D] = xd + wd * gd;
            }
        }
    }
}
