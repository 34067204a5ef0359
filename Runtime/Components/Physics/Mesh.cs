using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// Geometry for a <see cref="MeshCollider"/>: vertices and triangle indices (three per
    /// triangle), like the collision part of Unity's Mesh. Checked when assigned: finite
    /// vertices, indices in range, a whole number of triangles.
    /// </summary>
    public sealed class Mesh
    {
        Vector3[] _vertices = Array.Empty<Vector3>();
        int[] _triangles = Array.Empty<int>();

        /// <summary>An empty mesh.</summary>
        public Mesh() { }

        /// <summary>A mesh from vertices and triangle indices (copied).</summary>
        public Mesh(Vector3[] vertices, int[] triangles)
        {
            this.vertices = vertices;
            this.triangles = triangles;
        }

        /// <summary>The name (used in errors).</summary>
        public string name { get; set; } = "Mesh";

        /// <summary>Vertex positions in the mesh frame, metres (a copy).</summary>
        public Vector3[] vertices
        {
            get => (Vector3[])_vertices.Clone();
            set
            {
                if (value == null) throw new ArgumentNullException(nameof(vertices), $"Mesh '{name}': vertices cannot be null.");
                for (int i = 0; i < value.Length; i++)
                    if (!Validate.IsFinite(value[i])) throw new ArgumentException($"Mesh '{name}': vertices[{i}] must be finite, got {value[i]}.", nameof(vertices));
                _vertices = (Vector3[])value.Clone();
                Hull = null;
                Triangles = null;
            }
        }

        /// <summary>Triangle vertex indices, three per triangle (a copy).</summary>
        public int[] triangles
        {
            get => (int[])_triangles.Clone();
            set
            {
                if (value == null) throw new ArgumentNullException(nameof(triangles), $"Mesh '{name}': triangles cannot be null.");
                if (value.Length % 3 != 0) throw new ArgumentException($"Mesh '{name}': triangles must hold three indices per triangle, got {value.Length}.", nameof(triangles));
                for (int i = 0; i < value.Length; i++)
                    if ((uint)value[i] >= (uint)_vertices.Length)
                        throw new ArgumentException($"Mesh '{name}': triangles[{i}] = {value[i]} is outside the {_vertices.Length} vertices.", nameof(triangles));
                _triangles = (int[])value.Clone();
                Triangles = null;
            }
        }

        internal Vector3[] VerticesNoCopy => _vertices;
        // Built on first use by a collider and shared (hull for convex colliders, BVH mesh for static ones).
        internal ConvexHull? Hull;
        internal TriangleMesh? Triangles;
        internal int[] TrianglesNoCopy => _triangles;
    }
}
