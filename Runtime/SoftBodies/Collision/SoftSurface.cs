using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The boundary of one soft body as seen by other soft bodies: its surface vertices (in a
    /// spatial hash), its outward-wound surface triangles (a shell's own triangles, two-sided),
    /// and, refreshed once per step, their bounds, fastest speed and largest triangle box.
    /// </summary>
    internal sealed class SoftSurface
    {
        public readonly SoftBody Body;
        public readonly int[] Vertices;
        public readonly int[] Triangles;
        public readonly SpatialHash Hash;
        public Aabb Bounds;
        public float MaxSpeed;
        public float MaxTriangleExtent;

        public SoftSurface(SoftBody body)
        {
            Body = body;
            Triangles = body.Mesh.SurfaceTriangles.ToArray();
            Vertices = body.Mesh.SurfaceVertices();
            Hash = new SpatialHash(Vertices.Length);
        }

        /// <summary>Measures the surface where the step starts.</summary>
        public void Refresh()
        {
            Vector3[] x = Body.X, v = Body.V;
            Aabb bounds = Aabb.Empty;
            float speed2 = 0f;
            foreach (int i in Vertices)
            {
                bounds = Aabb.Union(bounds, x[i]);
                speed2 = MathF.Max(speed2, v[i].LengthSquared());
            }
            float extent = 0f;
            for (int t = 0; t < Triangles.Length; t += 3)
            {
                Vector3 a = x[Triangles[t]], b = x[Triangles[t + 1]], c = x[Triangles[t + 2]];
                Vector3 size = Vector3.Max(a, Vector3.Max(b, c)) - Vector3.Min(a, Vector3.Min(b, c));
                extent = MathF.Max(extent, MathF.Max(size.X, MathF.Max(size.Y, size.Z)));
            }
            Bounds = bounds;
            MaxSpeed = MathF.Sqrt(speed2);
            MaxTriangleExtent = extent;
        }
    }
}
