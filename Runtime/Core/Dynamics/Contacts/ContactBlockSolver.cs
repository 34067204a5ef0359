using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Solves the normal rows of two contact points together: the 2x2 mixed linear
    /// complementarity problem w = A x + b, x &gt;= 0, w &gt;= 0, x.w = 0 by enumerating its four
    /// cases (both active, only the first, only the second, neither), as in Box2D v2.x's block
    /// solver. With a soft row (Catto's soft step) the fixed point of the sequential update,
    /// v' + bias + gamma x = 0 with gamma = K (impulseScale / massScale), enters as
    /// A = K + diag(gamma); b = v + bias - K a, where a are the impulses before the solve.
    /// <para>
    /// Three- and four-point manifolds: the four normal rows of a face contact involve only
    /// three velocity components (one linear, two angular), so their 4x4 K is singular and a
    /// 4x4 enumeration would be ill-posed. Instead a four-point manifold is split into two
    /// pairs of points that lie far apart (each pair well conditioned, typically the diagonals
    /// of the contact quad) and a three-point one into its farthest pair plus one point solved
    /// alone; pairs whose K is ill-conditioned (cond &gt; 1000) fall back to the sequential rows.
    /// </para>
    /// </summary>
    internal static class ContactBlockSolver
    {
        const float MaxConditionNumber = 1000f;

        /// <summary>Chooses the pairs of a manifold and their K; leaves them unused where the block would be ill-conditioned.</summary>
        public static void Prepare(ref ContactConstraint c, ContactConstraintPoint[] points)
        {
            c.Block0 = ContactBlockPair.None;
            c.Block1 = ContactBlockPair.None;
            int n = c.PointCount, f = c.FirstPoint;
            if (n < 2) return;
            if (n == 2)
            {
                c.Block0 = MakePair(ref c, points, f, f + 1);
                return;
            }
            // The point farthest from point 0 pairs with it; for four points the other two pair up.
            int far = f + 1;
            float best = -1;
            for (int k = f + 1; k < f + n; k++)
            {
                float d = Vector3.DistanceSquared(points[k].Normal.AngularA, points[f].Normal.AngularA)
                        + Vector3.DistanceSquared(points[k].Normal.AngularB, points[f].Normal.AngularB);
                if (d > best) { best = d; far = k; }
            }
            c.Block0 = MakePair(ref c, points, f, far);
            if (n == 4)
            {
                int p = -1, q = -1;
                for (int k = f + 1; k < f + 4; k++)
                {
                    if (k == far) continue;
                    if (p < 0) p = k; else q = k;
                }
                c.Block1 = MakePair(ref c, points, p, q);
            }
        }

        static ContactBlockPair MakePair(ref ContactConstraint c, ContactConstraintPoint[] points, int i, int j)
        {
            ref ContactRow a = ref points[i].Normal;
            ref ContactRow b = ref points[j].Normal;
            float mass = AxisLockMath.InverseMassAlong(c.InvMassA, c.Normal) + AxisLockMath.InverseMassAlong(c.InvMassB, c.Normal);
            float k11 = mass + Vector3.Dot(a.AngularA, a.VelocityA) + Vector3.Dot(a.AngularB, a.VelocityB);
            float k22 = mass + Vector3.Dot(b.AngularA, b.VelocityA) + Vector3.Dot(b.AngularB, b.VelocityB);
            float k12 = mass + Vector3.Dot(a.AngularA, b.VelocityA) + Vector3.Dot(a.AngularB, b.VelocityB);
            float det = k11 * k22 - k12 * k12;
            if (!(k11 > 0 && k22 > 0) || !(k11 * k11 < MaxConditionNumber * det)) return ContactBlockPair.None;
            return new ContactBlockPair { I = i, J = j, K11 = k11, K12 = k12, K22 = k22 };
        }

        /// <summary>
        /// Solves one pair; <paramref name="bias1"/>/<paramref name="bias2"/> and
        /// <paramref name="gamma1"/>/<paramref name="gamma2"/> are the rows' velocity bias and
        /// softness (0 for rigid rows). Velocities are updated in place.
        /// </summary>
        public static void SolvePair(in ContactBlockPair pair, ContactConstraintPoint[] points, in ContactPairMotion m,
            float bias1, float gamma1, float bias2, float gamma2, ref BodyPairVelocity v)
        {
            ref ContactConstraintPoint p1 = ref points[pair.I];
            ref ContactConstraintPoint p2 = ref points[pair.J];
            Vector3 n = m.Normal;
            float a1 = p1.Normal.Impulse, a2 = p2.Normal.Impulse;
            float vn1 = p1.Normal.Velocity(n, v.LinearA, v.AngularA, v.LinearB, v.AngularB);
            float vn2 = p2.Normal.Velocity(n, v.LinearA, v.AngularA, v.LinearB, v.AngularB);
            float A11 = pair.K11 + gamma1, A22 = pair.K22 + gamma2, A12 = pair.K12;
            float b1 = vn1 + bias1 - (pair.K11 * a1 + pair.K12 * a2);
            float b2 = vn2 + bias2 - (pair.K12 * a1 + pair.K22 * a2);

            float x1, x2;
            // Case 1: both rows active, w = 0: x = -A^-1 b.
            float det = A11 * A22 - A12 * A12;
            float invDet = det != 0 ? 1f / det : 0f;
            x1 = -(A22 * b1 - A12 * b2) * invDet;
            x2 = -(A11 * b2 - A12 * b1) * invDet;
            if (!(x1 >= 0 && x2 >= 0))
            {
                // Case 2: only the first active (x2 = 0, w1 = 0, needs w2 >= 0).
                x1 = -b1 / A11;
                x2 = 0;
                if (!(x1 >= 0 && A12 * x1 + b2 >= 0))
                {
                    // Case 3: only the second active.
                    x1 = 0;
                    x2 = -b2 / A22;
                    if (!(x2 >= 0 && A12 * x2 + b1 >= 0))
                    {
                        // Case 4: neither active, which needs b >= 0; otherwise no case holds
                        // (possible only through round-off) and the impulses stay as they are.
                        x1 = 0;
                        x2 = 0;
                        if (!(b1 >= 0 && b2 >= 0)) return;
                    }
                }
            }
            float d1 = x1 - a1, d2 = x2 - a2;
            p1.Normal.Impulse = x1;
            p2.Normal.Impulse = x2;
            if (x1 > p1.MaxNormalImpulse)
            {
                ContactSolver.RecordImpact(ref p1, vn1);
                p1.MaxNormalImpulse = x1;
            }
            if (x2 > p2.MaxNormalImpulse)
            {
                ContactSolver.RecordImpact(ref p2, vn2);
                p2.MaxNormalImpulse = x2;
            }
            Vector3 p = (d1 + d2) * n;
            v.LinearA -= m.InvMassA * p;
            v.LinearB += m.InvMassB * p;
            v.AngularA -= d1 * p1.Normal.VelocityA + d2 * p2.Normal.VelocityA;
            v.AngularB += d1 * p1.Normal.VelocityB + d2 * p2.Normal.VelocityB;
        }
    }
}
