using System;
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Position correction of contacts for <see cref="PgsSolver"/>: non-linear Gauss-Seidel
    /// (Box2D v2.x's solvePositionConstraints). After the velocity solve and the position
    /// update, each point's remaining overlap beyond the slop is removed in part
    /// (Baumgarte factor beta, at most <c>maxCorrection</c> per pass) by moving the bodies
    /// directly. Velocities are not touched, so the correction adds no kinetic energy
    /// (no popping), unlike a velocity bias.
    /// </summary>
    internal static class ContactPositionSolver
    {
        /// <summary>Fraction of the overlap removed per pass (Box2D's b2_baumgarte).</summary>
        public const float Beta = 0.2f;

        /// <summary>
        /// One NGS pass over the manifold; returns the deepest overlap seen, m (&gt;= 0). With
        /// <paramref name="held"/> 1 (body A) or 2 (body B) that body is held still and the other
        /// takes the whole correction, through its own mass alone, of the overlap past
        /// <paramref name="heldSlop"/> instead of the linear slop (see SolverContext.HoldLightSupports).
        /// </summary>
        public static float Solve(ref ContactConstraint c, ContactConstraintPoint[] points, SolverBody[] bodies, in ContactStep step, byte held = 0, float heldSlop = 0f)
        {
            float slop = held != 0 ? heldSlop : step.LinearSlop, maxCorrection = step.MaxCorrection;
            ref SolverBody a = ref bodies[c.BodyA];
            ref SolverBody b = ref bodies[c.BodyB];
            Vector3 n = c.Normal;
            Vector3 mA = c.InvMassA, mB = c.InvMassB;
            float deepest = 0;
            for (int k = c.FirstPoint, end = c.FirstPoint + c.PointCount; k < end; k++)
            {
                ref ContactConstraintPoint p = ref points[k];
                float s = p.Separation + Vector3.Dot(n, b.DeltaPosition - a.DeltaPosition)
                        + Vector3.Dot(b.DeltaAngle, p.Normal.AngularB) - Vector3.Dot(a.DeltaAngle, p.Normal.AngularA);
                deepest = MathF.Max(deepest, -s);
                float C = Math.Clamp(Beta * (s + slop), -maxCorrection, 0f);
                if (C == 0) continue;
                float impulse = -C * p.Normal.EffectiveMass;
                if (held != 0)
                {
                    // One body moves: K is its own terms of the row's.
                    float single = held == 1
                        ? Vector3.Dot(n * n, mB) + Vector3.Dot(p.Normal.AngularB, p.Normal.VelocityB)
                        : Vector3.Dot(n * n, mA) + Vector3.Dot(p.Normal.AngularA, p.Normal.VelocityA);
                    if (!(single > 0f)) continue;
                    impulse = -C / single;
                }
                if (a.IsDynamic != 0 && held != 1)
                {
                    a.DeltaPosition -= mA * impulse * n;
                    a.Rotate(-impulse * p.Normal.VelocityA);
                }
                if (b.IsDynamic != 0 && held != 2)
                {
                    b.DeltaPosition += mB * impulse * n;
                    b.Rotate(impulse * p.Normal.VelocityB);
                }
            }
            return deepest;
        }
    }
}
