using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// One axis of the slab test of a line against a box centred on the origin: where
    /// p + t d crosses the two faces |x_k| = h_k. Ray casts and segment clipping run it over
    /// their axes, narrowing [enter, exit] to the stretch inside the box.
    /// </summary>
    internal static class Slab
    {
        /// <summary>
        /// The line's parameters at the two faces of axis <paramref name="k"/>, nearer first;
        /// <paramref name="enteredAtPlus"/> when it enters through the +h face. A line that runs
        /// parallel to the slab (|d_k| &lt; <paramref name="parallel"/>) gives false when it lies
        /// outside the slab, and -infinity and +infinity inside it (the slab bounds nothing).
        /// </summary>
        public static bool Cross(Vector3 p, Vector3 d, Vector3 h, int k, float parallel, out float enter, out float exit, out bool enteredAtPlus)
        {
            float pk = Component(p, k), dk = Component(d, k), hk = Component(h, k);
            enteredAtPlus = false;
            if (MathF.Abs(dk) < parallel)
            {
                enter = float.NegativeInfinity;
                exit = float.PositiveInfinity;
                return !(pk < -hk || pk > hk);
            }
            enter = (-hk - pk) / dk;
            exit = (hk - pk) / dk;
            if (enter > exit)
            {
                (enter, exit) = (exit, enter);
                enteredAtPlus = true;
            }
            return true;
        }

        static float Component(Vector3 v, int k) => k == 0 ? v.X : k == 1 ? v.Y : v.Z;
    }
}
