using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// Turns a <see cref="Mesh"/> into Core geometry: its convex hull (quickhull) or a static
    /// triangle mesh (with its BVH). Both are built once per mesh and shared by every collider
    /// that uses it; a Core rejection (coplanar points, degenerate triangles) is reported with
    /// the collider and the mesh named.
    /// </summary>
    internal static class MeshGeometry
    {
        public static ShapeGeometry Build(MeshCollider collider, Mesh mesh, bool convex)
        {
            try
            {
                if (convex)
                {
                    mesh.Hull ??= ConvexHull.Create(mesh.VerticesNoCopy);
                    return ShapeGeometry.ConvexHull(mesh.Hull);
                }
                mesh.Triangles ??= TriangleMesh.Create(mesh.VerticesNoCopy, mesh.TrianglesNoCopy);
                return ShapeGeometry.TriangleMesh(mesh.Triangles);
            }
            catch (ArgumentException e)
            {
                throw new ArgumentException($"{collider}: sharedMesh '{mesh.name}' cannot make a {(convex ? "convex hull" : "triangle mesh")}: {e.Message}", "sharedMesh", e);
            }
        }
    }
}
