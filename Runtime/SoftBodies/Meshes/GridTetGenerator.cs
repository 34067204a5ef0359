using System;
using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Tetrahedral meshes of a box on a regular grid, and of spheres and capsules carved out of
    /// such a grid. Vertices are centred on the origin; every tet is positively oriented.
    /// </summary>
    internal static class GridTetGenerator
    {
        // Cube corners by bit: x = 1, y = 2, z = 4.
        static readonly int[] SixSplit =
        {
            0, 1, 3, 7,   0, 1, 5, 7,   0, 2, 3, 7,   0, 2, 6, 7,   0, 4, 5, 7,   0, 4, 6, 7,
        };

        // Even cells: the central tet joins the corners of even bit count; odd cells mirror it.
        static readonly int[] FiveSplitEven =
        {
            0, 3, 5, 6,   1, 0, 3, 5,   2, 0, 3, 6,   4, 0, 5, 6,   7, 3, 5, 6,
        };

        static readonly int[] FiveSplitOdd =
        {
            1, 2, 4, 7,   0, 1, 2, 4,   3, 1, 2, 7,   5, 1, 4, 7,   6, 2, 4, 7,
        };

        /// <summary>A box of <paramref name="size"/> metres centred on the origin, cut into cells and each cell into tets.</summary>
        public static void Box(Vector3 size, int nx, int ny, int nz, TetSplit split, out Vector3[] vertices, out int[] tets)
        {
            int sx = nx + 1, sy = ny + 1, sz = nz + 1;
            vertices = new Vector3[sx * sy * sz];
            Vector3 cell = new Vector3(size.X / nx, size.Y / ny, size.Z / nz);
            Vector3 origin = -0.5f * size;
            for (int k = 0; k < sz; k++)
                for (int j = 0; j < sy; j++)
                    for (int i = 0; i < sx; i++)
                        vertices[i + sx * (j + sy * k)] = origin + new Vector3(i * cell.X, j * cell.Y, k * cell.Z);
            int perCell = split == TetSplit.Five ? 5 : 6;
            tets = new int[nx * ny * nz * perCell * 4];
            int t = 0;
            Span<int> corner = stackalloc int[8];
            for (int k = 0; k < nz; k++)
                for (int j = 0; j < ny; j++)
                    for (int i = 0; i < nx; i++)
                    {
                        // Mirrored: odd cells along an axis take the corners flipped along it.
                        int flip = split == TetSplit.SixMirrored ? (i & 1) | ((j & 1) << 1) | ((k & 1) << 2) : 0;
                        for (int c = 0; c < 8; c++)
                        {
                            int m = c ^ flip;
                            corner[c] = (i + (m & 1)) + sx * ((j + ((m >> 1) & 1)) + sy * (k + ((m >> 2) & 1)));
                        }
                        int[] pattern = split != TetSplit.Five ? SixSplit : ((i + j + k) & 1) == 0 ? FiveSplitEven : FiveSplitOdd;
                        for (int p = 0; p < pattern.Length; p += 4)
                        {
                            tets[t] = corner[pattern[p]];
                            tets[t + 1] = corner[pattern[p + 1]];
                            tets[t + 2] = corner[pattern[p + 2]];
                            tets[t + 3] = corner[pattern[p + 3]];
                            t += 4;
                        }
                    }
            OrientPositive(vertices, tets);
        }

        /// <summary>
        /// A solid carved from a grid: keeps the tets whose centroid satisfies
        /// <paramref name="inside"/>, peels off tets with all four corners on the boundary, drops
        /// unused vertices, moves each surface vertex onto the true surface
        /// (<paramref name="project"/>) where that keeps its tets well shaped, then smooths.
        /// </summary>
        public static void Carve(Vector3 size, int nx, int ny, int nz, Func<Vector3, bool> inside, Func<Vector3, Vector3> project,
            out Vector3[] vertices, out int[] tets)
        {
            Box(size, nx, ny, nz, TetSplit.Six, out Vector3[] gridVertices, out int[] gridTets);
            var kept = new List<int>(gridTets.Length);
            for (int t = 0; t < gridTets.Length; t += 4)
            {
                Vector3 c = 0.25f * (gridVertices[gridTets[t]] + gridVertices[gridTets[t + 1]] + gridVertices[gridTets[t + 2]] + gridVertices[gridTets[t + 3]]);
                if (inside(c)) for (int q = 0; q < 4; q++) kept.Add(gridTets[t + q]);
            }
            PeelSurfaceOnlyTets(gridVertices, kept);
            MeshCompaction.DropUnused(gridVertices, kept, out vertices, out tets);
            SnapSurface(vertices, tets, project);
        }

        // A tet whose four corners all lie on the boundary becomes inscribed in the surface once
        // they are snapped: for a cap a cell wide that is a sliver (and its corners get tiny
        // masses). Such tets are peeled off until none is left; the snap then restores the volume.
        static void PeelSurfaceOnlyTets(Vector3[] vertices, List<int> kept)
        {
            while (true)
            {
                int[] current = kept.ToArray();
                int[] surface = TetSurface.Extract(vertices, current);
                var onSurface = new bool[vertices.Length];
                foreach (int v in surface) onSurface[v] = true;
                kept.Clear();
                for (int t = 0; t < current.Length; t += 4)
                {
                    if (onSurface[current[t]] && onSurface[current[t + 1]] && onSurface[current[t + 2]] && onSurface[current[t + 3]]) continue;
                    for (int q = 0; q < 4; q++) kept.Add(current[t + q]);
                }
                if (kept.Count == current.Length) return;
            }
        }

        // Moving a surface vertex can flatten a thin tet; a move is kept only if every tet
        // around the vertex keeps a tenth of its grid volume. The smoothing pass then evens out
        // whatever slivers the snap or the guard left.
        static void SnapSurface(Vector3[] vertices, int[] tets, Func<Vector3, Vector3> project)
        {
            int[] surface = TetSurface.Extract(vertices, tets);
            var onSurface = new bool[vertices.Length];
            foreach (int v in surface) onSurface[v] = true;
            var incident = new List<int>[vertices.Length];
            for (int t = 0; t < tets.Length; t += 4)
                for (int q = 0; q < 4; q++)
                    (incident[tets[t + q]] ??= new List<int>()).Add(t);
            var restVolume = new float[tets.Length / 4];
            for (int t = 0; t < tets.Length; t += 4) restVolume[t / 4] = SignedVolume(vertices, tets, t);
            for (int v = 0; v < vertices.Length; v++)
            {
                if (!onSurface[v]) continue;
                Vector3 old = vertices[v];
                vertices[v] = project(old);
                foreach (int t in incident[v]!)
                {
                    if (SignedVolume(vertices, tets, t) < 0.1f * restVolume[t / 4])
                    {
                        vertices[v] = old;
                        break;
                    }
                }
            }
            Smooth(vertices, tets, surface, onSurface, incident, project);
        }

        const int SmoothingPasses = 8;

        // "Smart" Laplacian smoothing (Freitag, Jones & Plassmann 1995): each vertex moves to
        // the mean of its neighbours (surface vertices: of their surface neighbours, then back
        // onto the surface), and the move is kept only if the worst tet around it gets better.
        // A sliver's worst vertex is always among those that can move, so slivers open up while
        // no tet is ever made worse than the worst one it started from.
        static void Smooth(Vector3[] vertices, int[] tets, int[] surface, bool[] onSurface, List<int>[] incident, Func<Vector3, Vector3> project)
        {
            var neighbours = new HashSet<int>[vertices.Length];
            for (int v = 0; v < vertices.Length; v++) neighbours[v] = new HashSet<int>();
            for (int t = 0; t < tets.Length; t += 4)
                for (int a = 0; a < 4; a++)
                    for (int b = 0; b < 4; b++)
                    {
                        int va = tets[t + a], vb = tets[t + b];
                        // A surface vertex follows only its surface neighbours, which keeps it on the surface.
                        if (va != vb && (!onSurface[va] || onSurface[vb])) neighbours[va].Add(vb);
                    }
            for (int f = 0; f < surface.Length; f += 3)
                for (int a = 0; a < 3; a++)
                    neighbours[surface[f + a]].Add(surface[f + (a + 1) % 3]);
            for (int pass = 0; pass < SmoothingPasses; pass++)
            {
                for (int v = 0; v < vertices.Length; v++)
                {
                    if (neighbours[v].Count == 0) continue;
                    Vector3 mean = Vector3.Zero;
                    foreach (int n in neighbours[v]) mean += vertices[n];
                    mean /= neighbours[v].Count;
                    if (onSurface[v]) mean = project(mean);
                    float before = WorstQuality(vertices, tets, incident[v]!);
                    Vector3 old = vertices[v];
                    vertices[v] = mean;
                    if (WorstQuality(vertices, tets, incident[v]!) <= before) vertices[v] = old;
                }
            }
        }

        static float WorstQuality(Vector3[] vertices, int[] tets, List<int> around)
        {
            float worst = float.MaxValue;
            foreach (int t in around) worst = MathF.Min(worst, Quality(vertices, tets, t));
            return worst;
        }

        /// <summary>
        /// 6 sqrt(2) V / (mean edge length)^3 of the tet at <paramref name="t"/>: 1 for a regular
        /// tet, 0 for a flat one, negative for an inverted one; a grid (Kuhn) tet scores 0.51.
        /// </summary>
        public static float Quality(Vector3[] vertices, int[] tets, int t)
        {
            Vector3 a = vertices[tets[t]], b = vertices[tets[t + 1]], c = vertices[tets[t + 2]], d = vertices[tets[t + 3]];
            float edge = ((b - a).Length() + (c - a).Length() + (d - a).Length() + (c - b).Length() + (d - b).Length() + (d - c).Length()) / 6f;
            return 6f * MathF.Sqrt(2f) * SignedVolume(vertices, tets, t) / (edge * edge * edge);
        }

        /// <summary>Swaps the last two vertices of every negatively oriented tet.</summary>
        public static void OrientPositive(Vector3[] vertices, int[] tets)
        {
            for (int t = 0; t < tets.Length; t += 4)
            {
                if (SignedVolume(vertices, tets, t) < 0)
                {
                    int tmp = tets[t + 2];
                    tets[t + 2] = tets[t + 3];
                    tets[t + 3] = tmp;
                }
            }
        }

        /// <summary>det[x1-x0, x2-x0, x3-x0] / 6 of the tet starting at <paramref name="t"/> in the flat index list.</summary>
        public static float SignedVolume(Vector3[] vertices, int[] tets, int t)
        {
            Vector3 x0 = vertices[tets[t]];
            return Vector3.Dot(vertices[tets[t + 1]] - x0, Vector3.Cross(vertices[tets[t + 2]] - x0, vertices[tets[t + 3]] - x0)) / 6f;
        }
    }
}
