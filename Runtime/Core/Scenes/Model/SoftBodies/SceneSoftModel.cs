namespace Fulcrum.Scenes
{
    /// <summary>The <c>model</c> of a soft material.</summary>
    public enum SceneSoftModel : byte
    {
        /// <summary>
        /// <c>"stable-neo-hookean"</c>: Smith, de Goes and Kim, "Stable Neo-Hookean Flesh
        /// Simulation" (2018): defined for inverted elements (J &lt;= 0).
        /// </summary>
        StableNeoHookean = 0,
        /// <summary><c>"neo-hookean"</c>: Psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2 (needs J &gt; 0).</summary>
        NeoHookean = 1,
    }
}
