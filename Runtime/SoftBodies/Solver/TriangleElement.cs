using System.Numerics;
using System.Runtime.CompilerServices;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// One membrane triangle: vertex indices, the inverse of its 2x2 rest edge matrix Dm in a
    /// rest frame of the triangle (row-major), and its rest area. 32 bytes.
    /// </summary>
    internal struct TriangleElement
    {
        public int A, B, C;
        public float Inv00, Inv01, Inv10, Inv11;
        public float RestArea;

        /// <summary>The 3x2 deformation gradient F = [x1 - x0, x2 - x0] Dm^-1 at the vertex positions x0, x1, x2, as its columns f0, f1.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Deformation(Vector3 x0, Vector3 x1, Vector3 x2, out Vector3 f0, out Vector3 f1)
        {
            Vector3 e1 = x1 - x0, e2 = x2 - x0;
            f0 = e1 * Inv00 + e2 * Inv10;
            f1 = e1 * Inv01 + e2 * Inv11;
        }

        /// <summary>
        /// A constraint's gradients with respect to the vertices from its derivatives with respect to
        /// F's columns: dC/d(x_k) = sum_j dC/df_j Dm^-1[k, j] for k = 1, 2; x_0 takes minus the sum.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void VertexGradients(Vector3 df0, Vector3 df1, out Vector3 g0, out Vector3 g1, out Vector3 g2)
        {
            g1 = df0 * Inv00 + df1 * Inv01;
            g2 = df0 * Inv10 + df1 * Inv11;
            g0 = -(g1 + g2);
        }
    }
}
