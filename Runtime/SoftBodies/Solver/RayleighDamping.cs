using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Stiffness-proportional (Rayleigh) damping as a velocity pass after each substep's
    /// positions are final: every constraint C of stiffness k gets a dashpot of coefficient
    /// b = k tau (tau: <see cref="SoftBody.DampingTime"/>) acting on its rate dC/dt = grad C . v,
    /// solved implicitly per element: with G the element's constraint gradients, K = G W G^T
    /// and B = diag(b), the impulses mu = (K + (h B)^-1)^-1 G v and v -= W G^T mu.
    /// <para>
    /// Why not inside the position solve (Macklin et al. 2016, eq. 26, which this replaced): there
    /// the damping row gamma grad C . (x - x_prev), gamma = tau / h, multiplies the elastic row's
    /// stiffness by 1 + gamma (7 at tau = 0.01 s, 600 Hz), so one Gauss-Seidel iteration moves a
    /// stiff element only 1/7 of the way; the unconverged coupled solve is not dissipative and
    /// a thin swinging sheet gained up to 3.8 J of 11.8 J (0.2 J undamped); and the response
    /// depended on h through gamma. Here each element's update provably removes kinetic energy
    /// (dKE = -mu.(K + (hB)^-1) mu + mu.K mu / 2 &lt; 0, whatever the order), is exactly
    /// momentum- and angular-momentum-free (sum grad C = 0 and sum x x grad C = 0 at the x
    /// the gradients are taken at; a rigid velocity has grad C . v = 0, so rotation is not
    /// damped), and decays a mode of frequency w at tau w^2 / 2 per unit time for any h with
    /// tau w^2 h &lt;&lt; 1 (the factor per substep is 1 / (1 + tau w^2 h)).
    /// </para>
    /// </summary>
    internal static class RayleighDamping
    {
        /// <summary>
        /// Damps tets [start, end) (one colour: no shared vertex) along the gradients the last
        /// position iteration kept (<see cref="TetStream.Gradients"/>, taken just before that
        /// iteration's correction rather than at the final x). Any direction keeps the update
        /// dissipative and momentum-free; the torque-free projection about the final x keeps the
        /// angular momentum exact.
        /// </summary>
        public static void Tets(float deviatoricStiffness, float hydrostaticStiffness, TetStream tets,
            Vector3[] x, Vector3[] v, float[] w, float[] m, float[] free, int start, int end, float h, float dampingTime)
        {
            // 1 / (h b) per unit rest volume.
            float invD = 1f / (h * dampingTime * deviatoricStiffness), invH = 1f / (h * dampingTime * hydrostaticStiffness);
            int n = tets.Count;
            int[] vertices = tets.Vertices;
            float[] g = tets.Gradients;
            for (int e = start; e < end; e++)
            {
                int a = vertices[e], b = vertices[n + e], c = vertices[2 * n + e], d = vertices[3 * n + e];
                float w0 = w[a], w1 = w[b], w2 = w[c], w3 = w[d];
                if (w0 + w1 + w2 + w3 == 0f) continue;
                Vector3 gD0 = tets.Get(0, e), gD1 = tets.Get(3, e), gD2 = tets.Get(6, e), gD3 = tets.Get(9, e);
                Vector3 gH0 = tets.Get(12, e), gH1 = tets.Get(15, e), gH2 = tets.Get(18, e), gH3 = tets.Get(21, e);
                Vector3 v0 = v[a], v1 = v[b], v2 = v[c], v3 = v[d];
                float sD = Vector3.Dot(gD0, v0) + Vector3.Dot(gD1, v1) + Vector3.Dot(gD2, v2) + Vector3.Dot(gD3, v3);
                float sH = Vector3.Dot(gH0, v0) + Vector3.Dot(gH1, v1) + Vector3.Dot(gH2, v2) + Vector3.Dot(gH3, v3);
                float invV = 1f / tets.RestVolume[e];
                if (!XpbdConstraintPair.Solve(g[24 * n + e] + invD * invV, g[25 * n + e], g[26 * n + e] + invH * invV, sD, sH, out float mD, out float mH)) continue;
                Vector3 p0 = -(mD * gD0 + mH * gH0), p1 = -(mD * gD1 + mH * gH1), p2 = -(mD * gD2 + mH * gH2), p3 = -(mD * gD3 + mH * gH3);
                TorqueFree.ProjectIfFree(a, b, c, d, x, m, free, ref p0, ref p1, ref p2, ref p3);
                v[a] = v0 + w0 * p0;
                v[b] = v1 + w1 * p1;
                v[c] = v2 + w2 * p2;
                v[d] = v3 + w3 * p3;
            }
        }

        /// <summary>Damps membrane triangles [start, end).</summary>
        public static void Membranes(in MembraneEnergy model, float thickness, TriangleElement[] tris, Vector3[] x, Vector3[] v, float[] w,
            int start, int end, float h, float dampingTime)
        {
            float invD = 1f / (h * dampingTime * model.Mu * thickness), invH = 1f / (h * dampingTime * model.Lambda * thickness);
            for (int e = start; e < end; e++)
            {
                ref TriangleElement t = ref tris[e];
                float w0 = w[t.A], w1 = w[t.B], w2 = w[t.C];
                if (w0 + w1 + w2 == 0f) continue;
                t.Deformation(x[t.A], x[t.B], x[t.C], out Vector3 f0, out Vector3 f1);
                model.Constraints(f0, f1, out _, out Vector3 dD0, out Vector3 dD1, out _, out Vector3 dH0, out Vector3 dH1);
                t.VertexGradients(dD0, dD1, out Vector3 d0, out Vector3 d1, out Vector3 d2);
                t.VertexGradients(dH0, dH1, out Vector3 g0, out Vector3 g1, out Vector3 g2);
                Vector3 v0 = v[t.A], v1 = v[t.B], v2 = v[t.C];
                float sD = Vector3.Dot(d0, v0) + Vector3.Dot(d1, v1) + Vector3.Dot(d2, v2);
                float sH = Vector3.Dot(g0, v0) + Vector3.Dot(g1, v1) + Vector3.Dot(g2, v2);
                float kDD = w0 * d0.LengthSquared() + w1 * d1.LengthSquared() + w2 * d2.LengthSquared();
                float kHH = w0 * g0.LengthSquared() + w1 * g1.LengthSquared() + w2 * g2.LengthSquared();
                float kDH = w0 * Vector3.Dot(d0, g0) + w1 * Vector3.Dot(d1, g1) + w2 * Vector3.Dot(d2, g2);
                float invA = 1f / t.RestArea;
                if (!XpbdConstraintPair.Solve(kDD + invD * invA, kDH, kHH + invH * invA, sD, sH, out float mD, out float mH)) continue;
                v[t.A] = v0 - w0 * (mD * d0 + mH * g0);
                v[t.B] = v1 - w1 * (mD * d1 + mH * g1);
                v[t.C] = v2 - w2 * (mD * d2 + mH * g2);
            }
        }

        /// <summary>Damps bending hinges [start, end): b = tau / compliance.</summary>
        public static void Bends(BendElement[] bends, Vector3[] x, Vector3[] v, float[] w, int start, int end, float h, float dampingTime)
        {
            float hTau = h * dampingTime;
            for (int e = start; e < end; e++)
            {
                ref BendElement b = ref bends[e];
                float wa = w[b.A], wb = w[b.B], wc = w[b.C], wd = w[b.D];
                if (wa + wb + wc + wd == 0f) continue;
                if (!DihedralAngle.WithGradient(x[b.A], x[b.B], x[b.C], x[b.D], out _, out Vector3 ga, out Vector3 gb, out Vector3 gc, out Vector3 gd))
                    continue;
                Vector3 va = v[b.A], vb = v[b.B], vc = v[b.C], vd = v[b.D];
                float s = Vector3.Dot(ga, va) + Vector3.Dot(gb, vb) + Vector3.Dot(gc, vc) + Vector3.Dot(gd, vd);
                float k = wa * ga.LengthSquared() + wb * gb.LengthSquared() + wc * gc.LengthSquared() + wd * gd.LengthSquared();
                float denom = k + b.Compliance / hTau;
                if (!(denom > 1e-30f)) continue;
                float mu = s / denom;
                v[b.A] = va - wa * mu * ga;
                v[b.B] = vb - wb * mu * gb;
                v[b.C] = vc - wc * mu * gc;
                v[b.D] = vd - wd * mu * gd;
            }
        }
    }
}
