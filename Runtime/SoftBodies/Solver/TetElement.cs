using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// One tetrahedron as the solver reads it: 4 vertex indices, Dm^-1 (the inverse rest edge
    /// matrix, which plastic flow updates) and the rest volume. 56 bytes.
    /// </summary>
    internal struct TetElement
    {
        public int A, B, C, D;
        public Mat3 RestInverse;
        public float RestVolume;
    }
}
