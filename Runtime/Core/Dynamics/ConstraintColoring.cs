namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Greedy graph colouring of constraints: each constraint takes the lowest colour that
    /// neither of its dynamic bodies already has, so the constraints of one colour touch
    /// disjoint dynamic bodies and can be solved in any order or at once, with the same result.
    /// Static and kinematic bodies are never written by the solver and do not count. Colours
    /// are assigned in a fixed order, so the batches do not depend on the thread count. A
    /// constraint that finds all <see cref="MaxColors"/> colours taken goes to the overflow
    /// batch, which is solved on one thread after the colours.
    /// </summary>
    internal static class ConstraintColoring
    {
        /// <summary>Colours available; colour <see cref="MaxColors"/> is the overflow batch.</summary>
        public const int MaxColors = 64;

        /// <summary>Picks and records the colour of a constraint between solver bodies <paramref name="a"/> and <paramref name="b"/>.</summary>
        public static int Assign(ulong[] masks, int a, bool aDynamic, int b, bool bDynamic)
        {
            ulong used = (aDynamic ? masks[a] : 0) | (bDynamic ? masks[b] : 0);
            if (used == ulong.MaxValue) return MaxColors;
            int color = LowestClearBit(used);
            ulong bit = 1UL << color;
            if (aDynamic) masks[a] |= bit;
            if (bDynamic) masks[b] |= bit;
            return color;
        }

        static int LowestClearBit(ulong used)
        {
#if NET
            return System.Numerics.BitOperations.TrailingZeroCount(~used);
#else
            int c = 0;
            while ((used & 1UL) != 0)
            {
                used >>= 1;
                c++;
            }
            return c;
#endif
        }
    }
}
