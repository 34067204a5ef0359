using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// An immutable triangle mesh for static bodies, with its own bounding-volume hierarchy.
    /// Triangles are one-sided: their front is where (b - a) x (c - a) points, and a shape
    /// that sinks into a triangle is pushed out along that normal. Share one mesh between
    /// many shapes.
    /// </summary>
    public sealed class TriangleMesh : IBoundsSource
    {
        internal readonly Vector3[] Vertices;
        internal readonly int[] Indices;
        internal readonly Vector3[] Normals;
        internal readonly TriangleBvh Bvh;
        readonly Aabb _bounds;

        TriangleMesh(Vector3[] vertices, int[] indices, Vector3[] normals)
        {
            Vertices = vertices;
            Indices = indices;
            Normals = normals;
            Bvh = new TriangleBvh(vertices, indices);
            _bounds = Bvh.Nodes[0].Box;
        }

        /// <summary>
        /// Builds a mesh from vertices (shape frame, metres) and triangles (three vertex indices
        /// each). Throws an <see cref="ArgumentException"/> naming the bad entry: a non-finite
        /// vertex (mesh.vertices[i]), an index list that is empty or not a multiple of 3, an
        /// index out of range, or a degenerate (zero-area) triangle (mesh.triangles[k]).
        /// </summary>
        public static TriangleMesh Create(ReadOnlySpan<Vector3> vertices, ReadOnlySpan<int> triangles)
        {
            if (triangles.Length == 0 || triangles.Length % 3 != 0)
                throw new ArgumentException($"mesh.triangles must hold 3 indices per triangle and at least one triangle, got {triangles.Length} indices.", "mesh.triangles");
            float scale = 0;
            for (int i = 0; i < vertices.Length; i++)
            {
                if (!Validate.IsFinite(vertices[i]))
                    throw new ArgumentException($"mesh.vertices[{i}] must be finite, got {vertices[i]}.", "mesh.vertices");
                scale = MathF.Max(scale, MathF.Max(MathF.Abs(vertices[i].X), MathF.Max(MathF.Abs(vertices[i].Y), MathF.Abs(vertices[i].Z))));
            }
            int n = triangles.Length / 3;
            var normals = new Vector3[n];
            // Twice the area must exceed what float rounding of the coordinates can produce.
            float minCross = 1e-10f * MathF.Max(1e-12f, scale * scale);
            for (int t = 0; t < n; t++)
            {
                for (int k = 0; k < 3; k++)
                {
                    int v = triangles[3 * t + k];
                    if ((uint)v >= (uint)vertices.Length)
                        throw new ArgumentException($"mesh.triangles[{t}] uses vertex {v}, but there are {vertices.Length} vertices.", "mesh.triangles");
                }
                Vector3 a = vertices[triangles[3 * t]], b = vertices[triangles[3 * t + 1]], c = vertices[triangles[3 * t + 2]];
                Vector3 cross = Vector3.Cross(b - a, c - a);
                float len = cross.Length();
                if (!(len > minCross))
                    throw new ArgumentException($"mesh.triangles[{t}] is degenerate (zero area): vertices {a}, {b}, {c}.", "mesh.triangles");
                normals[t] = cross / len;
            }
            return new TriangleMesh(vertices.ToArray(), triangles.ToArray(), normals);
        }

        /// <summary>Writes the vertices and triangles; the normals and the hierarchy are rebuilt from them, deterministically.</summary>
        internal void WriteState(StateWriter w)
        {
            w.WriteArray(Vertices);
            w.WriteArray(Indices);
        }

        /// <summary>Reads what <see cref="WriteState"/> wrote, with the checks of <see cref="Create"/>.</summary>
        internal static TriangleMesh ReadState(StateReader r)
        {
            Vector3[] vertices = r.ReadArray<Vector3>("mesh vertices");
            int[] indices = r.ReadArray<int>("mesh triangles");
            try { return Create(vertices, indices); }
            catch (ArgumentException e) { throw r.Error(e.Message); }
        }

        /// <summary>Number of triangles.</summary>
        public int TriangleCount => Normals.Length;

        /// <summary>Number of vertices.</summary>
        public int VertexCount => Vertices.Length;

        /// <summary>Depth of the mesh's bounding-volume hierarchy (1 for a single leaf).</summary>
        public int BvhDepth => Bvh.Depth;

        /// <summary>The bounds in the shape frame.</summary>
        public Aabb LocalBounds => _bounds;

        /// <summary>The world bounds at a pose (the local bounds' corners transformed).</summary>
        public Aabb ComputeAabb(in Pose pose) => Aabb.Transform(pose, _bounds.Center, _bounds.Extents);

        internal void GetTriangle(int t, out Vector3 a, out Vector3 b, out Vector3 c)
        {
            a = Vertices[Indices[3 * t]];
            b = Vertices[Indices[3 * t + 1]];
            c = Vertices[Indices[3 * t + 2]];
        }

        // Triangle t placed at pose (mesh frame to world), for the users that work in world
        // space (continuous collision, debug drawing).
        internal void GetTriangle(int t, in Pose pose, out Vector3 a, out Vector3 b, out Vector3 c)
        {
            GetTriangle(t, out a, out b, out c);
            a = pose.TransformPoint(a);
            b = pose.TransformPoint(b);
            c = pose.TransformPoint(c);
        }

        // Triangle t (mesh frame), and whether its own bounds overlap box: a BVH leaf's box is
        // fattened, so the queries that gather contacts from its candidates drop here the ones
        // that only the fat box reaches.
        internal bool TriangleOverlaps(in Aabb box, int t, out Vector3 a, out Vector3 b, out Vector3 c)
        {
            GetTriangle(t, out a, out b, out c);
            return box.Overlaps(Aabb.OfTriangle(a, b, c));
        }
    }
}
