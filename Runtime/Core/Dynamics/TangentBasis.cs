using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Two unit tangents completing a unit normal to a right-handed frame (t1 x t2 = n), a
    /// smooth function of the normal so that friction impulses keep their meaning from step to
    /// step for warm starting. Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
    /// </summary>
    internal static class TangentBasis
    {
        public static void Build(Vector3 n, out Vector3 t1, out Vector3 t2)
        {
            float sign = n.Z >= 0 ? 1f : -1f;
            float a = -1f / (sign + n.Z);
            float b = n.X * n.Y * a;
            t1 = new Vector3(1f + sign * n.X * n.X * a, sign * b, -sign * n.X);
            t2 = new Vector3(b, sign + n.Y * n.Y * a, -n.Y);
        }
    }
}
