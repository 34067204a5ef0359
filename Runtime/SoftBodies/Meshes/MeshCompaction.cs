using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Drops the vertices no element uses (a carved grid's outside, an obj file's stray points),
    /// which a <see cref="SoftMesh"/> rejects: the used ones are kept in order of first use.
    /// </summary>
    internal static class MeshCompaction
    {
        /// <summary>
        /// The vertices of <paramref name="positions"/> that <paramref name="indices"/> use, in
        /// order of first use, and the indices renumbered into them.
        /// </summary>
        public static void DropUnused(IReadOnlyList<Vector3> positions, List<int> indices, out Vector3[] vertices, out int[] renumbered)
        {
            var remap = new int[positions.Count];
            for (int i = 0; i < remap.Length; i++) remap[i] = -1;
            var used = new List<Vector3>();
            renumbered = new int[indices.Count];
            for (int k = 0; k < indices.Count; k++)
            {
                int v = indices[k];
                if (remap[v] < 0)
                {
                    remap[v] = used.Count;
                    used.Add(positions[v]);
                }
                renumbered[k] = remap[v];
            }
            vertices = used.ToArray();
        }
    }
}
