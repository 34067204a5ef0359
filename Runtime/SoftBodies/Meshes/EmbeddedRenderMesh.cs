using System;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A render mesh driven by a tetrahedral soft body: each render vertex is bound once to the
    /// tet that contains it (or, outside the volume, the tet whose barycentric coordinates are
    /// least negative) and follows it as an affine combination of the tet's four corners.
    /// <see cref="Update"/> writes deformed positions and area-weighted vertex normals into the
    /// caller's buffers and allocates nothing.
    /// </summary>
    public sealed class EmbeddedRenderMesh
    {
        readonly int[] _tetOf;
        readonly Vector4[] _weights;
        readonly int[] _triangles;
        readonly int[] _tets;

        /// <summary>Binds <paramref name="renderVertices"/> (in the mesh's rest coordinates) to <paramref name="mesh"/>'s tets.</summary>
        public EmbeddedRenderMesh(SoftMesh mesh, Vector3[] renderVertices, int[] renderTriangles)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (renderVertices == null) throw new ArgumentNullException(nameof(renderVertices));
            if (renderTriangles == null) throw new ArgumentNullException(nameof(renderTriangles));
            if (mesh.IsShell) throw new ArgumentException("an embedding needs a volume (tetrahedral) mesh.", nameof(mesh));
            if (renderTriangles.Length % 3 != 0) throw new ArgumentException($"triangle index count must be a multiple of 3, got {renderTriangles.Length}.", nameof(renderTriangles));
            foreach (int i in renderTriangles)
                if ((uint)i >= (uint)renderVertices.Length) throw new ArgumentException($"triangle index {i} is out of range [0, {renderVertices.Length}).", nameof(renderTriangles));
            _tets = mesh.TetArray;
            Vector3[] x = mesh.VertexArray;
            _tetOf = new int[renderVertices.Length];
            _weights = new Vector4[renderVertices.Length];
            _triangles = (int[])renderTriangles.Clone();
            for (int v = 0; v < renderVertices.Length; v++)
            {
                float best = float.NegativeInfinity;
                // Brute force over the tets: binding happens once, at load.
                for (int t = 0; t < _tets.Length; t += 4)
                {
                    Vector4 w = Barycentric(x[_tets[t]], x[_tets[t + 1]], x[_tets[t + 2]], x[_tets[t + 3]], renderVertices[v]);
                    float worst = MathF.Min(MathF.Min(w.X, w.Y), MathF.Min(w.Z, w.W));
                    if (worst > best)
                    {
                        best = worst;
                        _tetOf[v] = t;
                        _weights[v] = w;
                    }
                }
            }
        }

        /// <summary>Number of render vertices.</summary>
        public int VertexCount => _tetOf.Length;

        /// <summary>
        /// Deformed render positions and unit normals from the soft body's vertex
        /// <paramref name="positions"/>; both outputs must hold <see cref="VertexCount"/> entries.
        /// </summary>
        public void Update(ReadOnlySpan<Vector3> positions, Span<Vector3> vertices, Span<Vector3> normals)
        {
            if (vertices.Length < _tetOf.Length || normals.Length < _tetOf.Length)
                throw new ArgumentException($"output buffers need {_tetOf.Length} entries, got {vertices.Length} and {normals.Length}.");
            for (int v = 0; v < _tetOf.Length; v++)
            {
                int t = _tetOf[v];
                Vector4 w = _weights[v];
                vertices[v] = w.X * positions[_tets[t]] + w.Y * positions[_tets[t + 1]] + w.Z * positions[_tets[t + 2]] + w.W * positions[_tets[t + 3]];
                normals[v] = Vector3.Zero;
            }
            // Unnormalised face normals have length twice the area: summing them weights by area.
            for (int f = 0; f < _triangles.Length; f += 3)
            {
                int a = _triangles[f], b = _triangles[f + 1], c = _triangles[f + 2];
                Vector3 n = Vector3.Cross(vertices[b] - vertices[a], vertices[c] - vertices[a]);
                normals[a] += n;
                normals[b] += n;
                normals[c] += n;
            }
            for (int v = 0; v < _tetOf.Length; v++)
            {
                float length = normals[v].Length();
                normals[v] = length > 0 ? normals[v] / length : Vector3.UnitY;
            }
        }

        // Barycentric coordinates of p in tet (a, b, c, d) by Cramer's rule on the edge matrix.
        static Vector4 Barycentric(Vector3 a, Vector3 b, Vector3 c, Vector3 d, Vector3 p)
        {
            Vector3 e1 = b - a, e2 = c - a, e3 = d - a, r = p - a;
            float det = Vector3.Dot(e1, Vector3.Cross(e2, e3));
            float w1 = Vector3.Dot(r, Vector3.Cross(e2, e3)) / det;
            float w2 = Vector3.Dot(e1, Vector3.Cross(r, e3)) / det;
            float w3 = Vector3.Dot(e1, Vector3.Cross(e2, r)) / det;
            return new Vector4(1 - w1 - w2 - w3, w1, w2, w3);
        }
    }
}
