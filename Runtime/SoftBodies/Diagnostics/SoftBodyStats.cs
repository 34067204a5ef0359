using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A snapshot of a soft body's state: what DESIGN.md's soft trace records per step
    /// (centroid, volumeRatio, minJ, energy) plus the totals behind them.
    /// </summary>
    public struct SoftBodyStats
    {
        /// <summary>Mass-weighted centre of the vertices, world, metres.</summary>
        public Vector3 Centroid;
        /// <summary>Current volume over rest volume (area for a shell); signed, so an inverted body is negative.</summary>
        public float VolumeRatio;
        /// <summary>The smallest element J = det F (area ratio for a shell).</summary>
        public float MinJ;
        /// <summary>Elastic (strain) energy, J; bending included for a shell.</summary>
        public float StrainEnergy;
        /// <summary>Kinetic energy of the vertices, J.</summary>
        public float KineticEnergy;
        /// <summary>Current signed volume (area for a shell), m^3 (m^2).</summary>
        public float Volume;
        /// <summary>Rest volume (area for a shell), m^3 (m^2).</summary>
        public float RestVolume;
        /// <summary>Total momentum of the vertices, kg m/s.</summary>
        public Vector3 Momentum;
    }
}
