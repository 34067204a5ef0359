using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The rest shape of a soft body, in its own (rest) coordinates, metres: either a
    /// tetrahedral volume mesh or a triangle shell (cloth). Immutable and validated when built:
    /// non-finite vertices, indices out of range, repeated vertices in an element, unused
    /// vertices and degenerate or inverted rest elements are rejected with the index of the
    /// offending vertex or element. Tets are positively oriented: det[x1-x0, x2-x0, x3-x0] &gt; 0.
    /// Several bodies may share one mesh.
    /// </summary>
    public sealed class SoftMesh
    {
        readonly Vector3[] _vertices;
        readonly int[] _tets;
        readonly int[] _triangles;
        readonly int[] _surface;
        readonly int[] _surfaceApexes = Array.Empty<int>();

        SoftMesh(Vector3[] vertices, int[] tets, int[] triangles)
        {
            _vertices = vertices;
            _tets = tets;
            _triangles = triangles;
            _surface = tets.Length > 0 ? TetSurface.Extract(vertices, tets, out _surfaceApexes) : triangles;
            Aabb bounds = Aabb.Empty;
            foreach (Vector3 v in vertices) bounds = Aabb.Union(bounds, v);
            Bounds = bounds;
        }

        /// <summary>Rest positions, metres.</summary>
        public ReadOnlySpan<Vector3> Vertices => _vertices;

        /// <summary>Tetrahedra: four vertex indices each (empty for a shell).</summary>
        public ReadOnlySpan<int> Tetrahedra => _tets;

        /// <summary>Shell triangles: three vertex indices each (empty for a volume mesh).</summary>
        public ReadOnlySpan<int> Triangles => _triangles;

        /// <summary>The boundary triangles, wound outward (for drawing and self-collision); a shell's own triangles.</summary>
        public ReadOnlySpan<int> SurfaceTriangles => _surface;

        /// <summary>Per boundary triangle of a tet mesh: the fourth vertex of the tet it bounds (empty for a shell).</summary>
        internal ReadOnlySpan<int> SurfaceApexes => _surfaceApexes;

        /// <summary>Number of vertices.</summary>
        public int VertexCount => _vertices.Length;

        /// <summary>Number of tetrahedra.</summary>
        public int TetrahedronCount => _tets.Length / 4;

        /// <summary>Number of shell triangles.</summary>
        public int TriangleCount => _triangles.Length / 3;

        /// <summary>True for a triangle shell (no tetrahedra).</summary>
        public bool IsShell => _tets.Length == 0;

        /// <summary>The rest bounds.</summary>
        public Aabb Bounds { get; }

        /// <summary>The mesh centre: the centre of <see cref="Bounds"/> (the point an initial deformation is taken about).</summary>
        public Vector3 Center => Bounds.Center;

        internal Vector3[] VertexArray => _vertices;
        internal int[] TetArray => _tets;
        internal int[] TriangleArray => _triangles;

        /// <summary>The vertices <see cref="SurfaceTriangles"/> use, ascending (a new array): those other bodies and self-collision touch.</summary>
        internal int[] SurfaceVertices()
        {
            var onSurface = new bool[_vertices.Length];
            foreach (int v in _surface) onSurface[v] = true;
            int n = 0;
            foreach (bool b in onSurface) if (b) n++;
            var ids = new int[n];
            n = 0;
            for (int i = 0; i < onSurface.Length; i++) if (onSurface[i]) ids[n++] = i;
            return ids;
        }

        /// <summary>A volume mesh from vertices and tets (four indices each); both arrays are copied and validated.</summary>
        public static SoftMesh FromTetrahedra(Vector3[] vertices, int[] tetrahedra)
        {
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (tetrahedra == null) throw new ArgumentNullException(nameof(tetrahedra));
            return Validated((Vector3[])vertices.Clone(), (int[])tetrahedra.Clone(), Array.Empty<int>());
        }

        /// <summary>A shell from vertices and triangles (three indices each); both arrays are copied and validated.</summary>
        public static SoftMesh FromTriangles(Vector3[] vertices, int[] triangles)
        {
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (triangles == null) throw new ArgumentNullException(nameof(triangles));
            return Validated((Vector3[])vertices.Clone(), Array.Empty<int>(), (int[])triangles.Clone());
        }

        /// <summary>
        /// A box of <paramref name="size"/> metres centred on the origin, <paramref name="cellsX"/> x
        /// <paramref name="cellsY"/> x <paramref name="cellsZ"/> cells, each cut into 6 (or 5) tets.
        /// The scene file's <c>mesh {type: "box", size, cells}</c>.
        /// </summary>
        public static SoftMesh Box(Vector3 size, int cellsX, int cellsY, int cellsZ, TetSplit split = TetSplit.Six)
        {
            Validate.Positive(size, "mesh.size");
            CheckCells(cellsX, "mesh.cells[0]");
            CheckCells(cellsY, "mesh.cells[1]");
            CheckCells(cellsZ, "mesh.cells[2]");
            if (split != TetSplit.Six && split != TetSplit.Five && split != TetSplit.SixMirrored) throw new ArgumentException($"mesh.split must be Six, Five or SixMirrored, got {split}.", "mesh.split");
            GridTetGenerator.Box(size, cellsX, cellsY, cellsZ, split, out Vector3[] v, out int[] t);
            return Validated(v, t, Array.Empty<int>());
        }

        /// <summary>
        /// A beam along x: <paramref name="length"/> by a square <paramref name="thickness"/>,
        /// <paramref name="cellsAlongLength"/> cells along x and as many across as keep the cells
        /// closest to cubes (at least one).
        /// </summary>
        public static SoftMesh Beam(float length, float thickness, int cellsAlongLength, TetSplit split = TetSplit.Six)
        {
            Validate.Positive(length, "mesh.length");
            Validate.Positive(thickness, "mesh.thickness");
            CheckCells(cellsAlongLength, "mesh.cells");
            int across = Math.Max(1, (int)MathF.Round(cellsAlongLength * thickness / length));
            return Box(new Vector3(length, thickness, thickness), cellsAlongLength, across, across, split);
        }

        // A tet is kept when its centroid lies this many cells inside the surface: a tet cut
        // by the surface with its centroid just inside would be stretched outward by the snap
        // into a thin element with light corners; dropping it and snapping the layer below
        // gives rounder elements (8 cells, 4.4 m/s impact: min J 0.63 -> 0.66 and the energy
        // spike above gravity's work 246 J -> 95 J).
        const float KeepMargin = 0.25f;

        /// <summary>
        /// A ball of <paramref name="radius"/> metres carved from a grid of
        /// <paramref name="cellsAcross"/> cells along its diameter: tets whose centroid lies a
        /// quarter cell inside are kept, surface vertices are moved onto the sphere, the mesh is
        /// smoothed so that no element is a sliver, and it is scaled to the ball's volume.
        /// </summary>
        public static SoftMesh Sphere(float radius, int cellsAcross)
        {
            Validate.Positive(radius, "mesh.radius");
            CheckCells(cellsAcross, "mesh.cells");
            if (cellsAcross < Scenes.SceneSoftSphere.MinCells)
                throw new ArgumentException($"mesh.cells must be >= {Scenes.SceneSoftSphere.MinCells} for a sphere (fewer carve no tet), got {cellsAcross}.", "mesh.cells");
            float keep = radius - KeepMargin * 2 * radius / cellsAcross;
            GridTetGenerator.Carve(new Vector3(2 * radius), cellsAcross, cellsAcross, cellsAcross,
                p => p.LengthSquared() <= keep * keep,
                p => p.LengthSquared() > 1e-12f ? p * (radius / p.Length()) : p,
                out Vector3[] v, out int[] t);
            // The snapped surface is a polyhedron inscribed in the sphere and falls short of its
            // volume by the chord sag (5 % at 8 cells across); scaling to the ball's volume keeps
            // the mass and the mean radius right (the vertices then sit 1.6 % outside at 8 cells).
            float volume = 0;
            for (int k = 0; k < t.Length; k += 4) volume += GridTetGenerator.SignedVolume(v, t, k);
            float scale = MathF.Pow(4f / 3f * MathF.PI * radius * radius * radius / volume, 1f / 3f);
            for (int i = 0; i < v.Length; i++) v[i] *= scale;
            return Validated(v, t, Array.Empty<int>());
        }

        /// <summary>
        /// A capsule along y (radius, half-height of the inner segment), carved from a grid with
        /// <paramref name="cellsAcross"/> cells along its diameter.
        /// </summary>
        public static SoftMesh Capsule(float radius, float halfHeight, int cellsAcross)
        {
            Validate.Positive(radius, "mesh.radius");
            Validate.NonNegative(halfHeight, "mesh.halfHeight");
            CheckCells(cellsAcross, "mesh.cells");
            if (cellsAcross < Scenes.SceneSoftSphere.MinCells)
                throw new ArgumentException($"mesh.cells must be >= {Scenes.SceneSoftSphere.MinCells} for a capsule (fewer carve no tet), got {cellsAcross}.", "mesh.cells");
            float cell = 2 * radius / cellsAcross;
            int along = Math.Max(cellsAcross, (int)MathF.Ceiling((2 * halfHeight + 2 * radius) / cell));
            Vector3 size = new Vector3(2 * radius, along * cell, 2 * radius);
            Vector3 Axis(Vector3 p) => new Vector3(0, Math.Clamp(p.Y, -halfHeight, halfHeight), 0);
            float keep = radius - KeepMargin * cell;
            GridTetGenerator.Carve(size, cellsAcross, along, cellsAcross,
                p => (p - Axis(p)).LengthSquared() <= keep * keep,
                p =>
                {
                    Vector3 d = p - Axis(p);
                    return d.LengthSquared() > 1e-12f ? Axis(p) + d * (radius / d.Length()) : p;
                },
                out Vector3[] v, out int[] t);
            return Validated(v, t, Array.Empty<int>());
        }

        /// <summary>A volume mesh from the text of a TetGen .node and .ele file pair (see TetGen's file formats).</summary>
        public static SoftMesh FromTetGen(string nodeText, string eleText)
        {
            TetGenReader.Read(nodeText, eleText, out Vector3[] v, out int[] t);
            return Validated(v, t, Array.Empty<int>());
        }

        /// <summary>
        /// A rectangular cloth of <paramref name="sizeX"/> by <paramref name="sizeZ"/> metres in the
        /// x-z plane (normal +y), centred on the origin, with cellsX x cellsZ quads of two triangles.
        /// </summary>
        public static SoftMesh Cloth(float sizeX, float sizeZ, int cellsX, int cellsZ)
        {
            Validate.Positive(sizeX, "mesh.size[0]");
            Validate.Positive(sizeZ, "mesh.size[1]");
            CheckCells(cellsX, "mesh.cells[0]");
            CheckCells(cellsZ, "mesh.cells[1]");
            ClothGridGenerator.Generate(sizeX, sizeZ, cellsX, cellsZ, out Vector3[] v, out int[] t);
            return Validated(v, Array.Empty<int>(), t);
        }

        /// <summary>A shell from the surface of a Wavefront OBJ text (v and f statements).</summary>
        public static SoftMesh FromObj(string objText)
        {
            ObjReader.Read(objText, out Vector3[] v, out int[] t);
            return Validated(v, Array.Empty<int>(), t);
        }

        static void CheckCells(int cells, string name)
        {
            if (cells < 1 || cells > 1024) throw new ArgumentException($"{name} must be in [1, 1024], got {cells}.", name);
        }

        static SoftMesh Validated(Vector3[] vertices, int[] tets, int[] triangles)
        {
            if (vertices.Length == 0) throw new ArgumentException("mesh has no vertices.", "mesh.Vertices");
            for (int i = 0; i < vertices.Length; i++)
                if (!Validate.IsFinite(vertices[i]))
                    throw new ArgumentException($"mesh vertex {i} must be finite, got {vertices[i]}.", "mesh.Vertices");
            var used = new bool[vertices.Length];
            if (tets.Length > 0)
            {
                if (tets.Length % 4 != 0) throw new ArgumentException($"mesh tetrahedra need four indices each; got {tets.Length} indices.", "mesh.Tetrahedra");
                for (int t = 0; t < tets.Length; t += 4)
                {
                    CheckElement(tets, t, 4, vertices.Length, "tetrahedron", "mesh.Tetrahedra", used);
                    Vector3 x0 = vertices[tets[t]];
                    Vector3 e1 = vertices[tets[t + 1]] - x0, e2 = vertices[tets[t + 2]] - x0, e3 = vertices[tets[t + 3]] - x0;
                    float volume = Vector3.Dot(e1, Vector3.Cross(e2, e3)) / 6f;
                    float edge = MathF.Max(e1.Length(), MathF.Max(e2.Length(), e3.Length()));
                    // Relative to the longest edge, so the check does not depend on units.
                    if (!(MathF.Abs(volume) > 1e-6f * edge * edge * edge))
                        throw new ArgumentException($"tetrahedron {t / 4} is degenerate: its rest volume is {volume} m^3.", "mesh.Tetrahedra");
                    if (volume < 0)
                        throw new ArgumentException($"tetrahedron {t / 4} is inverted: its rest volume is {volume} m^3 (order its vertices so that det[x1-x0, x2-x0, x3-x0] > 0).", "mesh.Tetrahedra");
                }
            }
            else
            {
                if (triangles.Length == 0) throw new ArgumentException("mesh has neither tetrahedra nor triangles.", "mesh.Triangles");
                if (triangles.Length % 3 != 0) throw new ArgumentException($"mesh triangles need three indices each; got {triangles.Length} indices.", "mesh.Triangles");
                for (int t = 0; t < triangles.Length; t += 3)
                {
                    CheckElement(triangles, t, 3, vertices.Length, "triangle", "mesh.Triangles", used);
                    Vector3 x0 = vertices[triangles[t]];
                    Vector3 e1 = vertices[triangles[t + 1]] - x0, e2 = vertices[triangles[t + 2]] - x0;
                    float area = 0.5f * Vector3.Cross(e1, e2).Length();
                    float edge = MathF.Max(e1.Length(), e2.Length());
                    if (!(area > 1e-6f * edge * edge))
                        throw new ArgumentException($"triangle {t / 3} is degenerate: its rest area is {area} m^2.", "mesh.Triangles");
                }
            }
            for (int i = 0; i < used.Length; i++)
                if (!used[i]) throw new ArgumentException($"mesh vertex {i} belongs to no element (it would have no mass).", "mesh.Vertices");
            return new SoftMesh(vertices, tets, triangles);
        }

        static void CheckElement(int[] indices, int start, int arity, int vertexCount, string kind, string field, bool[] used)
        {
            for (int q = 0; q < arity; q++)
            {
                int v = indices[start + q];
                if ((uint)v >= (uint)vertexCount)
                    throw new ArgumentException($"{kind} {start / arity} names vertex {v}, but the mesh has {vertexCount}.", field);
                for (int r = 0; r < q; r++)
                    if (indices[start + r] == v)
                        throw new ArgumentException($"{kind} {start / arity} uses vertex {v} twice.", field);
                used[v] = true;
            }
        }
    }
}
