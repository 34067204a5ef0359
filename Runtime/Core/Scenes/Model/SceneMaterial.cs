namespace Fulcrum.Scenes
{
    /// <summary>A named entry of the <c>materials</c> object.</summary>
    public sealed class SceneMaterial
    {
        /// <summary>The member name under <c>materials</c>; bodies refer to it.</summary>
        public string Name { get; set; } = "";

        /// <summary><c>friction</c>: Coulomb coefficient, &gt;= 0. Default: 0.6.</summary>
        public float Friction { get; set; } = 0.6f;

        /// <summary><c>restitution</c>: in [0, 1]. Default: 0.</summary>
        public float Restitution { get; set; }

        /// <summary>
        /// <c>density</c>, kg/m^3, &gt; 0; null when not given (bodies then use 1000). A body
        /// may not give a <c>mass</c> when its material gives a density.
        /// </summary>
        public float? Density { get; set; }
    }
}
