namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The hyperelastic energy of a soft body. The scene file names them
    /// <c>"stable-neo-hookean"</c> and <c>"neo-hookean"</c> (see <see cref="NeoHookeanMaterial.ParseModel"/>).
    /// </summary>
    public enum MaterialModel : byte
    {
        /// <summary>
        /// Smith, de Goes and Kim 2018, "Stable Neo-Hookean Flesh Simulation":
        /// Psi = mu/2 (I_C - 3) + lambda/2 (J - alpha)^2 - mu/2 ln(I_C + 1), alpha = 1 + 3 mu / (4 lambda).
        /// Defined and smooth for every F, inverted elements included. Scene name "stable-neo-hookean".
        /// </summary>
        StableNeoHookean = 0,
        /// <summary>
        /// The classic compressible Neo-Hookean energy Psi = mu/2 (I_C - 3) - mu ln J + lambda/2 (ln J)^2,
        /// with ln J continued linearly below <see cref="NeoHookeanEnergy.MinJ"/> so that it stays
        /// defined for J &lt;= 0. Scene name "neo-hookean".
        /// </summary>
        NeoHookean = 1,
    }
}
