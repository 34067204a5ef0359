using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The deformation gradient of a linear tetrahedron, F = Ds Dm^-1 (Ds, Dm: edge matrices
    /// [x1-x0, x2-x0, x3-x0] now and at rest), and the chain rule back to its vertices.
    /// det F is signed: a mirrored element has J &lt; 0.
    /// </summary>
    internal static class DeformationGradient
    {
        /// <summary>
        /// Below this value of C_D^2 (about 1.5 |strain|^2, so a strain under 1e-6) an element
        /// counts as at rest: float positions cannot resolve such a strain, and the cone point
        /// of C_D at rest would otherwise turn rounding noise into motion.
        /// </summary>
        public const double RestTolerance = 1e-12;

        /// <summary>F of a tet from its current vertices and its rest inverse Dm^-1.</summary>
        public static Mat3 Of(Vector3 x0, Vector3 x1, Vector3 x2, Vector3 x3, in Mat3 restInverse) =>
            new Mat3(x1 - x0, x2 - x0, x3 - x0) * restInverse;

        /// <summary>cof F = dJ/dF = J F^-T: column i is the cross product of the other two columns.</summary>
        public static Mat3 Cofactor(in Mat3 f) =>
            new Mat3(Vector3.Cross(f.C1, f.C2), Vector3.Cross(f.C2, f.C0), Vector3.Cross(f.C0, f.C1));

        /// <summary>
        /// The gradient of a scalar c(F) with respect to the four vertices, given G = dc/dF:
        /// since F = sum_k (x_k - x_0) r_k^T with r_k^T the rows of Dm^-1, dc/dx_k = G r_k
        /// (k = 1..3), the columns of G Dm^-T, and dc/dx_0 = -(g1 + g2 + g3).
        /// </summary>
        public static void VertexGradients(in Mat3 g, in Mat3 restInverse, out Vector3 g0, out Vector3 g1, out Vector3 g2, out Vector3 g3)
        {
            g1 = g * restInverse.R0;
            g2 = g * restInverse.R1;
            g3 = g * restInverse.R2;
            g0 = -(g1 + g2 + g3);
        }
    }
}
