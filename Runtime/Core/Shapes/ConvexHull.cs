using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// An immutable convex polyhedron in its shape frame: vertices, planar faces (vertex loops
    /// counter-clockwise seen from outside, with outward unit normals) and unique edges.
    /// </summary>
    internal sealed class ConvexHull
    {
        internal readonly Vector3[] Vertices;
        internal readonly Vector3[] FaceNormals;
        internal readonly float[] FaceOffsets;     // n . x = offset on the face
        internal readonly int[] FaceStart;         // face f uses FaceVertices[FaceStart[f] .. FaceStart[f + 1])
        internal readonly int[] FaceVertices;
        internal readonly int[] EdgeVertices;      // edge e joins EdgeVertices[2e] and [2e + 1]
        internal readonly int[] EdgeFaces;         // the two faces of edge e

        internal ConvexHull(Vector3[] vertices, Vector3[] faceNormals, float[] faceOffsets, int[] faceStart, int[] faceVertices, int[] edgeVertices, int[] edgeFaces)
        {
            Vertices = vertices;
            FaceNormals = faceNormals;
            FaceOffsets = faceOffsets;
            FaceStart = faceStart;
            FaceVertices = faceVertices;
            EdgeVertices = edgeVertices;
            EdgeFaces = edgeFaces;
        }

        /// <summary>Number of vertices.</summary>
        public int VertexCount => Vertices.Length;

        /// <summary>Number of faces.</summary>
        public int FaceCount => FaceNormals.Length;

        /// <summary>Number of edges.</summary>
        public int EdgeCount => EdgeVertices.Length / 2;

        /// <summary>The vertex farthest along a local direction.</summary>
        internal int SupportIndex(Vector3 direction)
        {
            int best = 0;
            float max = Vector3.Dot(Vertices[0], direction);
            for (int i = 1; i < Vertices.Length; i++)
            {
                float d = Vector3.Dot(Vertices[i], direction);
                if (d > max) { max = d; best = i; }
            }
            return best;
        }
    }
}
