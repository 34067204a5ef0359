using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The Gilbert-Johnson-Keerthi distance between two convex cores (Gilbert, Johnson and
    /// Keerthi 1988; the formulation of van den Bergen, "Collision Detection in Interactive
    /// 3D Environments", 2004): the simplex of support points of A - B walks towards the
    /// origin until the support mapping makes no more progress. Radii are not included.
    /// </summary>
    internal static class Gjk
    {
        const int MaxIterations = 48;

        /// <summary>
        /// The distance between the cores of <paramref name="a"/> and <paramref name="b"/>
        /// (0 when they overlap) with the closest points on each. <paramref name="simplex"/>
        /// is the final simplex (a tetrahedron holding the origin when they overlap, for EPA).
        /// </summary>
        public static float Distance(in SupportShape a, in SupportShape b, out Vector3 pointA, out Vector3 pointB, out Simplex simplex)
        {
            simplex = default;
            Vector3 d = b.Center - a.Center;
            if (d.LengthSquared() < 1e-12f) d = Vector3.UnitX;
            Vector3 sa = a.Support(-d, out int ia), sb = b.Support(d, out int ib);
            simplex.V0 = new SimplexVertex(sa, ia, sb, ib);
            simplex.Count = 1;

            float previous = float.MaxValue;
            for (int iteration = 0; iteration < MaxIterations; iteration++)
            {
                if (!simplex.Solve())
                {
                    simplex.WitnessPoints(out pointA, out pointB);
                    return 0;
                }
                Vector3 v = simplex.ClosestPoint();
                float vv = v.LengthSquared();
                if (vv < CollisionMargins.CoreTolerance * CollisionMargins.CoreTolerance) break;
                // A progress stall (float noise near the minimum) ends the walk.
                if (vv >= previous) break;
                previous = vv;

                Vector3 wa = a.Support(-v, out ia), wb = b.Support(v, out ib);
                Vector3 w = wa - wb;
                // Converged: the new support point is no closer along v than v itself
                // (relative tolerance on the squared distance, van den Bergen eq. 4.8).
                if (vv - Vector3.Dot(v, w) <= 1e-6f * vv) break;
                if (simplex.Contains(ia, ib)) break;
                switch (simplex.Count)
                {
                    case 1: simplex.V1 = new SimplexVertex(wa, ia, wb, ib); break;
                    case 2: simplex.V2 = new SimplexVertex(wa, ia, wb, ib); break;
                    default: simplex.V3 = new SimplexVertex(wa, ia, wb, ib); break;
                }
                simplex.Count++;
            }
            simplex.WitnessPoints(out pointA, out pointB);
            return Vector3.Distance(pointA, pointB);
        }
    }
}
