namespace Fulcrum
{
    /// <summary>
    /// How two shapes' friction (or restitution) combine at a contact. When the two shapes ask
    /// for different modes, the one later in this list wins (Unity's priority:
    /// Average &lt; Minimum &lt; Multiply &lt; Maximum).
    /// </summary>
    public enum CombineMode : byte
    {
        /// <summary>(a + b) / 2.</summary>
        Average = 0,
        /// <summary>min(a, b).</summary>
        Minimum = 1,
        /// <summary>a * b.</summary>
        Multiply = 2,
        /// <summary>max(a, b).</summary>
        Maximum = 3,
    }

    /// <summary>Applies a <see cref="CombineMode"/>.</summary>
    public static class Combine
    {
        /// <summary>Combines two coefficients with the higher-priority of the two modes.</summary>
        public static float Values(float a, CombineMode modeA, float b, CombineMode modeB)
        {
            CombineMode mode = modeA > modeB ? modeA : modeB;
            switch (mode)
            {
                case CombineMode.Minimum: return a < b ? a : b;
                case CombineMode.Multiply: return a * b;
                case CombineMode.Maximum: return a > b ? a : b;
                default: return 0.5f * (a + b);
            }
        }
    }
}
