namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>
    /// The settings every engine is given, taken from Fulcrum's defaults so that "matched" means
    /// the values Fulcrum ships with: same step, substeps, iterations per substep, friction, mass,
    /// contact stiffness where the engine exposes one, gravity, no damping, no sleeping, one thread.
    /// </summary>
    public sealed class PeerSettings
    {
        /// <summary>Time step, s.</summary>
        public float Dt { get; init; } = 1f / 60f;
        /// <summary>Substeps per step.</summary>
        public int Substeps { get; init; } = WorldSettings.Default.Substeps;
        /// <summary>Velocity iterations per substep.</summary>
        public int Iterations { get; init; } = WorldSettings.Default.Iterations;
        /// <summary>Unbiased relax passes per substep (Fulcrum TGS, Jitter2; Bepu has none).</summary>
        public int RelaxIterations { get; init; } = WorldSettings.Default.RelaxIterations;
        /// <summary>Coulomb friction of every pair.</summary>
        public float Friction { get; init; } = 0.6f;
        /// <summary>Mass of every dynamic box, kg.</summary>
        public float BoxMass { get; init; } = 1f;
        /// <summary>Gravity along y, m/s^2.</summary>
        public float GravityY { get; init; } = WorldSettings.Default.Gravity.Y;
        /// <summary>Soft contact stiffness, Hz (Fulcrum, Bepu): what Fulcrum's default reaches at 60 Hz x 4 substeps.</summary>
        public float ContactHertz { get; init; } = 60f;
        /// <summary>Soft contact damping ratio (Fulcrum, Bepu).</summary>
        public float ContactDampingRatio { get; init; } = WorldSettings.Default.ContactDampingRatio;
        /// <summary>Fastest push-out of overlap, m/s (Fulcrum MaxContactPushSpeed, Bepu MaximumRecoveryVelocity).</summary>
        public float MaxPushSpeed { get; init; } = WorldSettings.Default.MaxContactPushSpeed;
    }
}
