namespace Fulcrum
{
    /// <summary>
    /// How two shapes' friction (or restitution) combine at a contact. The numbers are Unity's
    /// <c>PhysicsMaterialCombine</c> (Average 0, Multiply 1, Minimum 2, Maximum 3), so a value
    /// cast from Unity means the same here. When the two shapes ask for different modes the one
    /// of higher priority wins, also as in Unity: Average &lt; Minimum &lt; Multiply &lt; Maximum.
    /// </summary>
    public enum CombineMode : byte
    {
        /// <summary>(a + b) / 2.</summary>
        Average = 0,
        /// <summary>a * b.</summary>
        Multiply = 1,
        /// <summary>min(a, b).</summary>
        Minimum = 2,
        /// <summary>max(a, b).</summary>
        Maximum = 3,
    }

    /// <summary>Applies a <see cref="CombineMode"/>.</summary>
    public static class Combine
    {
        /// <summary>Combines two coefficients with the higher-priority of the two modes.</summary>
        public static float Values(float a, CombineMode modeA, float b, CombineMode modeB)
        {
            CombineMode mode = Priority(modeA) > Priority(modeB) ? modeA : modeB;
            switch (mode)
            {
                case CombineMode.Minimum: return a < b ? a : b;
                case CombineMode.Multiply: return a * b;
                case CombineMode.Maximum: return a > b ? a : b;
                default: return 0.5f * (a + b);
            }
        }

        /// <summary>Unity's order of precedence: Average &lt; Minimum &lt; Multiply &lt; Maximum.</summary>
        public static int Priority(CombineMode mode) => mode switch
        {
            CombineMode.Minimum => 1,
            CombineMode.Multiply => 2,
            CombineMode.Maximum => 3,
            _ => 0,
        };
    }
}
