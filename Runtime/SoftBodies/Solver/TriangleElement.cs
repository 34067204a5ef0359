namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// One membrane triangle: vertex indices, the inverse of its 2x2 rest edge matrix Dm in a
    /// rest frame of the triangle (row-major), and its rest area. 32 bytes.
    /// </summary>
    internal struct TriangleElement
    {
        public int A, B, C;
        public float Inv00, Inv01, Inv10, Inv11;
        public float RestArea;
    }
}
