using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A rectangular sheet of triangles in the x-z plane (normal +y), centred on the origin.
    /// The diagonal of each quad alternates like a checkerboard so the sheet has no preferred
    /// shear direction.
    /// </summary>
    internal static class ClothGridGenerator
    {
        public static void Generate(float sizeX, float sizeZ, int nx, int nz, out Vector3[] vertices, out int[] triangles)
        {
            int sx = nx + 1;
            vertices = new Vector3[sx * (nz + 1)];
            for (int k = 0; k <= nz; k++)
                for (int i = 0; i <= nx; i++)
                    vertices[i + sx * k] = new Vector3(sizeX * ((float)i / nx - 0.5f), 0, sizeZ * ((float)k / nz - 0.5f));
            triangles = new int[nx * nz * 6];
            int t = 0;
            for (int k = 0; k < nz; k++)
                for (int i = 0; i < nx; i++)
                {
                    int v00 = i + sx * k, v10 = v00 + 1, v01 = v00 + sx, v11 = v01 + 1;
                    // Winding (a, b, c) with (b - a) x (c - a) along +y: +z edge first, then +x.
                    if (((i + k) & 1) == 0)
                    {
                        t = Add(triangles, t, v00, v01, v11);
                        t = Add(triangles, t, v00, v11, v10);
                    }
                    else
                    {
                        t = Add(triangles, t, v00, v01, v10);
                        t = Add(triangles, t, v10, v01, v11);
                    }
                }
        }

        static int Add(int[] triangles, int t, int a, int b, int c)
        {
            triangles[t] = a;
            triangles[t + 1] = b;
            triangles[t + 2] = c;
            return t + 3;
        }
    }
}
