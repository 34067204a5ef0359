using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The slab test of a ray segment against a box (Kay and Kajiya 1986): the segment
    /// origin + t d, t in [0, maxT], meets the box when the intervals where it lies between
    /// each pair of planes overlap. A zero component of d gives an infinite inverse, which the
    /// comparisons handle; the NaN from 0 * inf (origin on a slab plane) is treated as a hit.
    /// </summary>
    internal static class RaySlab
    {
        /// <summary>1 / d per component, infinity where d is zero.</summary>
        public static Vector3 Inverse(Vector3 d) => new Vector3(1f / d.X, 1f / d.Y, 1f / d.Z);

        /// <summary>True when the segment meets the box; <paramref name="tEnter"/> is where it enters (0 if it starts inside).</summary>
        public static bool Test(in Aabb box, Vector3 origin, Vector3 inverseDirection, float maxT, out float tEnter)
        {
            Vector3 t1 = (box.Min - origin) * inverseDirection;
            Vector3 t2 = (box.Max - origin) * inverseDirection;
            Vector3 lo = Vector3.Min(t1, t2), hi = Vector3.Max(t1, t2);
            float enter = MaxNotNaN(MaxNotNaN(MaxNotNaN(0f, lo.X), lo.Y), lo.Z);
            float exit = MinNotNaN(MinNotNaN(MinNotNaN(maxT, hi.X), hi.Y), hi.Z);
            tEnter = enter;
            return enter <= exit;
        }

        static float MaxNotNaN(float a, float b) => b > a ? b : a;
        static float MinNotNaN(float a, float b) => b < a ? b : a;
    }
}
