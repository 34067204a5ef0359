using System;

namespace Fulcrum.Components
{
    /// <summary>
    /// Turns a <see cref="Mesh"/> into Core geometry (a convex hull or a triangle mesh). The
    /// hull and mesh kinds are not built into Fulcrum.Core yet, so this throws a clear
    /// <see cref="NotSupportedException"/> until they are.
    /// </summary>
    internal static class MeshGeometry
    {
        public static ShapeGeometry Build(MeshCollider collider, Mesh mesh, bool convex)
        {
            throw new NotSupportedException(
                $"{collider}: {(convex ? "convex hull" : "triangle mesh")} shapes are not available in this build of Fulcrum.Core " +
                "(ShapeGeometry has no hull or mesh factory yet); use Box, Sphere or Capsule colliders.");
        }
    }
}
