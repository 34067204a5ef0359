using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>The boundary of a tet mesh: the faces that belong to exactly one tet, wound outward.</summary>
    internal static class TetSurface
    {
        // For a tet with det[x1-x0, x2-x0, x3-x0] > 0 these windings have outward normals.
        static readonly int[] Faces = { 0, 2, 1,   0, 1, 3,   0, 3, 2,   1, 2, 3 };
        // The vertex each face leaves out.
        static readonly int[] Apex = { 3, 2, 1, 0 };

        /// <summary>Flat list of outward boundary triangles (three vertex indices each).</summary>
        public static int[] Extract(Vector3[] vertices, int[] tets) => Extract(vertices, tets, out _);

        /// <summary>
        /// <see cref="Extract(Vector3[], int[])"/>, with each triangle's apex: the fourth vertex of
        /// the tet the triangle bounds (behind the triangle, on the body's side).
        /// </summary>
        public static int[] Extract(Vector3[] vertices, int[] tets, out int[] apexes)
        {
            var count = new Dictionary<(int, int, int), int>(tets.Length);
            for (int t = 0; t < tets.Length; t += 4)
                for (int f = 0; f < 12; f += 3)
                {
                    var key = Key(tets[t + Faces[f]], tets[t + Faces[f + 1]], tets[t + Faces[f + 2]]);
                    count.TryGetValue(key, out int n);
                    count[key] = n + 1;
                }
            var surface = new List<int>();
            var apex = new List<int>();
            for (int t = 0; t < tets.Length; t += 4)
                for (int f = 0; f < 12; f += 3)
                {
                    int a = tets[t + Faces[f]], b = tets[t + Faces[f + 1]], c = tets[t + Faces[f + 2]];
                    if (count[Key(a, b, c)] != 1) continue;
                    surface.Add(a);
                    surface.Add(b);
                    surface.Add(c);
                    apex.Add(tets[t + Apex[f / 3]]);
                }
            apexes = apex.ToArray();
            return surface.ToArray();
        }

        static (int, int, int) Key(int a, int b, int c)
        {
            if (a > b) (a, b) = (b, a);
            if (b > c) (b, c) = (c, b);
            if (a > b) (a, b) = (b, a);
            return (a, b, c);
        }
    }
}
