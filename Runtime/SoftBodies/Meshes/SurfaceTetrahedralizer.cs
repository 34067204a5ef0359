using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Volume meshes of any closed triangle surface: a cubic grid over the surface's bounds is
    /// cut into Kuhn tets, the tets whose centroid lies inside (generalised winding number) and a
    /// quarter cell from the surface are kept, boundary vertices are snapped onto the nearest
    /// surface point and the mesh is smoothed (see <see cref="GridTetGenerator.Carve"/>).
    /// </summary>
    public static class SurfaceTetrahedralizer
    {
        // Same margin as the sphere: a tet whose centroid is within a quarter cell of the
        // surface would become a thin cap once its corners are snapped.
        const float KeepMargin = 0.25f;

        /// <summary>
        /// Tetrahedralises the closed surface (<paramref name="vertices"/>, three indices per
        /// triangle, any winding) with <paramref name="resolution"/> cells along its longest side.
        /// Cost is O(grid vertices x triangles): meant for load time, not per step. Errors name the
        /// scene fields they come from (mesh.resolution, mesh.file).
        /// </summary>
        public static SoftMesh Tetrahedralize(Vector3[] vertices, int[] triangles, int resolution)
        {
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (triangles == null) throw new ArgumentNullException(nameof(triangles));
            if (resolution < 2 || resolution > 256)
                throw new ArgumentOutOfRangeException("mesh.resolution", $"mesh.resolution must be in [2, 256], got {resolution}.");
            if (triangles.Length == 0 || triangles.Length % 3 != 0)
                throw new ArgumentException($"triangle index count must be a positive multiple of 3, got {triangles.Length}.", "mesh.file");
            for (int i = 0; i < vertices.Length; i++)
                if (!float.IsFinite(vertices[i].X) || !float.IsFinite(vertices[i].Y) || !float.IsFinite(vertices[i].Z))
                    throw new ArgumentException($"vertex {i} is not finite.", "mesh.file");
            for (int i = 0; i < triangles.Length; i++)
                if ((uint)triangles[i] >= (uint)vertices.Length)
                    throw new ArgumentException($"triangle {i / 3} index {triangles[i]} is out of range [0, {vertices.Length}).", "mesh.file");

            Vector3 min = new Vector3(float.MaxValue), max = new Vector3(float.MinValue);
            foreach (Vector3 v in vertices)
            {
                min = Vector3.Min(min, v);
                max = Vector3.Max(max, v);
            }
            Vector3 extent = max - min;
            float longest = MathF.Max(extent.X, MathF.Max(extent.Y, extent.Z));
            if (!(longest > 0)) throw new ArgumentException("the surface has no extent.", "mesh.file");
            float cell = longest / resolution;
            // One spare cell per axis so the grid covers the surface with room on every side.
            int nx = (int)MathF.Ceiling(extent.X / cell) + 1, ny = (int)MathF.Ceiling(extent.Y / cell) + 1, nz = (int)MathF.Ceiling(extent.Z / cell) + 1;
            Vector3 centre = 0.5f * (min + max);
            float keep = KeepMargin * cell;
            GridTetGenerator.Carve(new Vector3(nx * cell, ny * cell, nz * cell), nx, ny, nz,
                p =>
                {
                    Vector3 q = p + centre;
                    return WindingNumber(vertices, triangles, q) > 0.5f
                        && (ClosestPoint(vertices, triangles, q) - q).LengthSquared() >= keep * keep;
                },
                p => ClosestPoint(vertices, triangles, p + centre) - centre,
                out Vector3[] tv, out int[] tt);
            if (tt.Length == 0)
                throw new ArgumentException($"no cell of the grid lies inside the surface at resolution {resolution}: is it closed, or is the resolution too coarse?", "mesh.resolution");
            for (int i = 0; i < tv.Length; i++) tv[i] += centre;
            return SoftMesh.FromTetrahedra(tv, tt);
        }

        /// <summary>
        /// The generalised winding number of the surface about <paramref name="p"/> (Jacobson et
        /// al. 2013): the sum of the triangles' signed solid angles over 4 pi, by the formula of
        /// Van Oosterom and Strackee (1983). About 1 inside a closed surface wound outward, 0
        /// outside; its magnitude is used, so either winding works.
        /// </summary>
        public static float WindingNumber(Vector3[] vertices, int[] triangles, Vector3 p)
        {
            double total = 0;
            for (int t = 0; t < triangles.Length; t += 3)
            {
                Vector3 a = vertices[triangles[t]] - p, b = vertices[triangles[t + 1]] - p, c = vertices[triangles[t + 2]] - p;
                float la = a.Length(), lb = b.Length(), lc = c.Length();
                double numerator = Vector3.Dot(a, Vector3.Cross(b, c));
                double denominator = (double)la * lb * lc + Vector3.Dot(a, b) * lc + Vector3.Dot(b, c) * la + Vector3.Dot(c, a) * lb;
                total += 2 * Math.Atan2(numerator, denominator);
            }
            return (float)Math.Abs(total / (4 * Math.PI));
        }

        /// <summary>The point of the surface nearest to <paramref name="p"/> (brute force over the triangles).</summary>
        public static Vector3 ClosestPoint(Vector3[] vertices, int[] triangles, Vector3 p)
        {
            Vector3 best = vertices[triangles[0]];
            float bestSq = float.MaxValue;
            for (int t = 0; t < triangles.Length; t += 3)
            {
                Vector3 q = ClosestOnTriangle(p, vertices[triangles[t]], vertices[triangles[t + 1]], vertices[triangles[t + 2]]);
                float d = (q - p).LengthSquared();
                if (d < bestSq)
                {
                    bestSq = d;
                    best = q;
                }
            }
            return best;
        }

        // Voronoi regions of the triangle's vertices, edges and face (Ericson, Real-Time
        // Collision Detection, 5.1.5).
        static Vector3 ClosestOnTriangle(Vector3 p, Vector3 a, Vector3 b, Vector3 c)
        {
            Vector3 ab = b - a, ac = c - a, ap = p - a;
            float d1 = Vector3.Dot(ab, ap), d2 = Vector3.Dot(ac, ap);
            if (d1 <= 0 && d2 <= 0) return a;
            Vector3 bp = p - b;
            float d3 = Vector3.Dot(ab, bp), d4 = Vector3.Dot(ac, bp);
            if (d3 >= 0 && d4 <= d3) return b;
            float vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
            Vector3 cp = p - c;
            float d5 = Vector3.Dot(ab, cp), d6 = Vector3.Dot(ac, cp);
            if (d6 >= 0 && d5 <= d6) return c;
            float vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
            float va = d3 * d6 - d5 * d4;
            if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / (d4 - d3 + d5 - d6) * (c - b);
            float denom = 1f / (va + vb + vc);
            return a + ab * (vb * denom) + ac * (vc * denom);
        }
    }
}
