using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A convex rigid shape's corners, edges and tips (spheres, boxes, capsules, hulls; a plane
    /// has none, and a triangle mesh's vertices are not tested) against a tet body's surface
    /// triangles. The
    /// vertex contacts (<see cref="ShapeContactSolver"/>) push only the soft body's vertices out
    /// of a shape, so a feature smaller than the mesh spacing passes between them: a 0.5 m crate
    /// (10 kg to 1 t) dropped corner first on a 0.3 m slab of 0.15 m cells came to rest with its
    /// corner 12 cm below the slab's surface, the surface around it undisturbed (now 0.1-3.0 mm:
    /// <c>FeatureContactTests</c>).
    /// <para>
    /// Each outward surface triangle whose plane the shape's deepest point has crossed (its
    /// support point against the triangle's normal, less its radius), with that point's
    /// projection inside the triangle, the shape's centre in front of the plane and the point
    /// no deeper than the triangle's tet, is pushed back along the normal as one
    /// zero-compliance XPBD constraint C = n . (p - a) &gt;= 0 between the triangle (its three
    /// vertices weighted by the barycentric coordinates b_k of the projection: generalised
    /// inverse mass sum b_k^2 w_k) and the shape's body (<see cref="RigidCoupling.InverseMassAt"/>):
    /// the point-triangle contact of Mueller et al. 2020, section 3.5, with the rigid point as
    /// the point. Coulomb friction follows, on the substep's slip at the point, within mu times
    /// the triangle's normal corrections of the substep (as the vertex contacts do); without it
    /// a crate balanced on its corner slid off the slab. A push takes out at most the collision
    /// radius per pass (see <see cref="Solve"/>), and a triangle meets only a point that came in
    /// through it or a triangle next to it (one sharing a vertex with it met in this substep or
    /// the last, or at most that radius past its plane when the substep began).
    /// </para>
    /// <para>
    /// A shape lying flat on the surface is held off it by the vertex contacts at the collision
    /// radius and does not cross a triangle's plane. Two cases are left to the vertex contacts:
    /// a triangle whose tet is crushed below the volume floor's trigger (J &lt; 0.5; pushed along
    /// its own normal too, the rim of a slab crushed by a 10 t crate was driven through its tets,
    /// min J -4.8), and a body more than <see cref="MaxLoadRatio"/> times the soft body's mass.
    /// </para>
    /// </summary>
    internal static class ShapeFeatureContacts
    {
        /// <summary>
        /// The heaviest body, as a multiple of the soft body's mass, whose features meet the
        /// triangles: 100. Beyond it the load crushes the body to its volume floor wherever it
        /// lands (a 10 t crate on a 43 kg slab, 230 times), and pushing the triangles around
        /// the crushed region inverted tets there (min J -3 to -4 with E 1e4 Pa, 10 t from 0.5
        /// and 2 m; the bar is no inverted element): the vertex contacts and the floor carry
        /// such a load alone.
        /// </summary>
        public const float MaxLoadRatio = 100f;

        /// <summary>
        /// One pass of shape <paramref name="geometry"/> at <paramref name="pose"/> (owned by body
        /// slot <paramref name="owner"/>) against the outward-wound surface
        /// <paramref name="triangles"/> of a tet body, each with the fourth vertex of its tet in
        /// <paramref name="apex"/> and six times that tet's rest volume in <paramref name="restVolume6"/>;
        /// <paramref name="pushed"/> and <paramref name="held"/> (per triangle) are the substep's
        /// normal corrections and the friction spent against them; <paramref name="metLast"/> and
        /// <paramref name="metNow"/> (per vertex) which vertices' triangles a shape's feature met in
        /// the last substep and in this one.
        /// </summary>
        public static void Solve(SoftBody body, int[] triangles, int[] apex, float[] restVolume6, in ShapeGeometry geometry, in Pose pose,
            int owner, RigidCoupling coupling, float h, float mu, float[] pushed, float[] held, bool[] metLast, bool[] metNow)
        {
            Vector3[] x = body.X, xPrev = body.XPrev;
            float[] w = body.W;
            float radius = body.CollisionRadius;
            SupportShape shape = SupportShape.From(geometry, pose);
            Aabb bounds = geometry.ComputeAabb(pose);
            Vector3 centre = bounds.Center;
            for (int t = 0; t < triangles.Length; t += 3)
            {
                int i0 = triangles[t], i1 = triangles[t + 1], i2 = triangles[t + 2];
                Vector3 a = x[i0], b = x[i1], c = x[i2];
                if (!bounds.Overlaps(Aabb.OfTriangle(a, b, c))) continue;
                Vector3 n = Vector3.Cross(b - a, c - a);
                float area2 = n.Length();
                if (!(area2 > 1e-12f)) continue;
                n /= area2;
                // Behind the face: a shape on the far side, or one the soft body has swallowed
                // (the vertex contacts push those out).
                if (Vector3.Dot(n, centre - a) <= 0f) continue;
                Vector3 deepest = shape.Support(-n, out _) - shape.Radius * n;
                float separation = Vector3.Dot(n, deepest - a);
                if (separation >= 0f) continue;
                int k = t / 3;
                // The tet's height over the triangle: a crushed tet is left alone, and a point
                // beyond the apex did not come in through this triangle (a 3.4 t body 0.64 m past
                // the plane of a soft box's side triangles, whose tets reach 0.14 m, was pushed
                // out through them and gained 99 kJ: HeavyOnPinnedSoftTests).
                float height = -Vector3.Dot(n, x[apex[k]] - a);
                if (height * area2 < VolumeFloor.Trigger * restVolume6[k] || -separation > height) continue;
                // The projection's barycentric coordinates: the point over the face's interior
                // (the closest point of the triangle is then the projection, in its face region).
                TriangleClosestPoint.Find(deepest, a, b, c, out Vector3 weights);
                float s = weights.X, v = weights.Y, u = weights.Z;
                if (!(s > 0f && v > 0f && u > 0f)) continue;

                float w0 = w[i0], w1 = w[i1], w2 = w[i2];
                float wt = s * s * w0 + v * v * w1 + u * u * w2;
                float wb = coupling.InverseMassAt(owner, deepest, n);
                if (!(wt + wb > 0f)) continue;
                // A triangle meets a point that came in through it or through a triangle next to
                // it: one it or a triangle sharing a vertex with it met in this substep or the
                // last (the contact moves across the surface as the body deforms and slides), or
                // one that was at most the collision radius past its plane when the substep began
                // (its overlap less the substep's approach, the point's motion into the triangle
                // relative to it along -n). A point already deep when no triangle around it has
                // met it came in elsewhere, and pushed out of this triangle at the collision
                // radius per pass it takes energy from nowhere: out of a pinned end face
                // (immovable, so the body took it all), a 30 kg ball sunk into a soft box next to
                // it took 3 m/s a substep and left at 29 m/s, a 3.4 t body 20 m/s and 9e5 J (soft
                // fuzz seed 117), and a 300 kg ball 0.11 m past a triangle with one pinned vertex
                // 2.2 m/s in a step (HeavyOnPinnedSoftTests). The vertex contacts and the triangles
                // it came through meet it. (Stopping such a point at the triangle, taking out the
                // substep's approach alone, was tried: soft fuzz seed 53 then ended inverted.
                // Counting only the triangle itself, not its neighbours, let a heavy body sink
                // through a crushed soft box, soft fuzz seed 227.)
                Vector3 moved = s * (x[i0] - xPrev[i0]) + v * (x[i1] - xPrev[i1]) + u * (x[i2] - xPrev[i2]);
                float approach = Vector3.Dot(n, moved - coupling.PointVelocity(owner, deepest) * h);
                if (!(metLast[i0] || metLast[i1] || metLast[i2] || metNow[i0] || metNow[i1] || metNow[i2]) && -separation - approach > radius) continue;
                metNow[i0] = metNow[i1] = metNow[i2] = true;
                // At most the collision radius per pass: the overlap comes out over the
                // substep's iterations. Taken out at once, a slab crushed by a 1 t crate landing
                // square had its rim triangles driven through their tets (min J -4.8).
                float dl = MathF.Min(-separation, radius) / (wt + wb);
                x[i0] -= s * w0 * dl * n;
                x[i1] -= v * w1 * dl * n;
                x[i2] -= u * w2 * dl * n;
                coupling.Push(owner, deepest, dl * n, h);
                pushed[k] += dl;

                moved = s * (x[i0] - xPrev[i0]) + v * (x[i1] - xPrev[i1]) + u * (x[i2] - xPrev[i2]);
                Vector3 relative = moved - coupling.PointVelocity(owner, deepest) * h;
                Vector3 tangent = relative - Vector3.Dot(relative, n) * n;
                float slip = tangent.Length();
                if (!(slip > 1e-9f)) continue;
                Vector3 along = tangent / slip;
                float dlt = slip / (wt + coupling.InverseMassAt(owner, deepest, along));
                float cone = mu * pushed[k] - held[k];
                if (dlt > cone) dlt = cone > 0f ? cone : 0f;
                held[k] += dlt;
                x[i0] -= s * w0 * dlt * along;
                x[i1] -= v * w1 * dlt * along;
                x[i2] -= u * w2 * dlt * along;
                coupling.Push(owner, deepest, dlt * along, h);
            }
        }
    }
}
