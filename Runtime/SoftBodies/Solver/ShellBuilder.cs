using System.Collections.Generic;
using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Builds the membrane triangles and bending hinges of a shell from its rest mesh.
    /// Bending: a sheet of thickness t has rigidity D = E t^3 / (12 (1 - nu^2)). The discrete
    /// shell energy (Grinspun et al. 2003, "Discrete Shells") per edge is
    /// k_B 3 |e|^2 / (A1 + A2) (theta - theta_rest)^2; wrapping a strip of hinges of spacing a
    /// and length w on a cylinder of radius R (theta = a / R) gives k_B 3 / R^2 per area against
    /// the continuum D / (2 R^2), so k_B = D / 6, i.e. a hinge stiffness
    /// k = D |e|^2 / (A1 + A2) for the energy k/2 (theta - theta_rest)^2.
    /// </summary>
    internal static class ShellBuilder
    {
        public static TriangleElement[] Triangles(Vector3[] rest, int[] triangles)
        {
            var tris = new TriangleElement[triangles.Length / 3];
            for (int t = 0; t < tris.Length; t++)
            {
                int a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
                Vector3 e1 = rest[b] - rest[a], e2 = rest[c] - rest[a];
                Vector3 n = Vector3.Cross(e1, e2);
                float area = 0.5f * n.Length();
                Vector3 t1 = Vector3.Normalize(e1);
                Vector3 t2 = Vector3.Cross(Vector3.Normalize(n), t1);
                // Dm in the triangle's own frame: [[e1.t1, e2.t1], [0, e2.t2]].
                float m00 = Vector3.Dot(e1, t1), m01 = Vector3.Dot(e2, t1), m11 = Vector3.Dot(e2, t2);
                float invDet = 1f / (m00 * m11);
                tris[t] = new TriangleElement
                {
                    A = a, B = b, C = c,
                    Inv00 = m11 * invDet, Inv01 = -m01 * invDet,
                    Inv10 = 0f, Inv11 = m00 * invDet,
                    RestArea = area,
                };
            }
            return tris;
        }

        /// <summary>One hinge per edge shared by exactly two triangles; compliance 1/k with k as in the type's remarks.</summary>
        public static BendElement[] Bends(Vector3[] rest, int[] triangles, float rigidity)
        {
            var firstOwner = new Dictionary<(int, int), (int Tri, int Opposite, int U, int V)>();
            var bends = new List<BendElement>();
            var seen = new HashSet<(int, int)>();
            for (int t = 0; t < triangles.Length / 3; t++)
            {
                for (int k = 0; k < 3; k++)
                {
                    int u = triangles[3 * t + k], v = triangles[3 * t + (k + 1) % 3], o = triangles[3 * t + (k + 2) % 3];
                    var key = u < v ? (u, v) : (v, u);
                    if (!firstOwner.TryGetValue(key, out var first))
                    {
                        firstOwner[key] = (t, o, u, v);
                        continue;
                    }
                    if (!seen.Add(key)) continue; // a third triangle on the edge: non-manifold, no hinge
                    // Triangle A = (A, C, D) in the first owner's winding (o, u, v); the second
                    // triangle then reads (B, D, C) when the two are wound consistently.
                    int a = first.Opposite, c = first.U, d = first.V, b = o;
                    float area = TriangleArea(rest, first.Tri, triangles) + TriangleArea(rest, t, triangles);
                    float edge2 = (rest[d] - rest[c]).LengthSquared();
                    bends.Add(new BendElement
                    {
                        A = a, B = b, C = c, D = d,
                        RestAngle = DihedralAngle.Of(rest[a], rest[b], rest[c], rest[d]),
                        Compliance = area / (rigidity * edge2),
                    });
                }
            }
            return bends.ToArray();
        }

        static float TriangleArea(Vector3[] rest, int t, int[] triangles) =>
            0.5f * Vector3.Cross(rest[triangles[3 * t + 1]] - rest[triangles[3 * t]], rest[triangles[3 * t + 2]] - rest[triangles[3 * t]]).Length();

        /// <summary>D = E t^3 / (12 (1 - nu^2)), N m.</summary>
        public static float Rigidity(in NeoHookeanMaterial material, float thickness) =>
            material.YoungsModulus * thickness * thickness * thickness / (12f * (1f - material.PoissonRatio * material.PoissonRatio));
    }
}
