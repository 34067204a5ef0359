namespace Fulcrum.SoftBodies
{
    /// <summary>How a grid cell (a cube) is cut into tetrahedra.</summary>
    public enum TetSplit : byte
    {
        /// <summary>
        /// Six tets around the cell's main diagonal (the Kuhn/Freudenthal split). Every cell is
        /// cut the same way, so neighbouring faces match; the elements are all congruent.
        /// </summary>
        Six = 0,
        /// <summary>
        /// Five tets: a central regular tet and four corner tets. Cells alternate between the
        /// two mirror images by the parity of i + j + k so that face diagonals match. Fewer
        /// elements, but the central tet is twice the size of the others.
        /// </summary>
        Five = 1,
        /// <summary>
        /// Six tets around a main diagonal as in <see cref="Six"/>, with every other cell along
        /// each axis mirrored across the face it shares with its neighbour (the reflected Kuhn
        /// split): faces still match (a mirror fixes the shared face), and the mesh has no
        /// preferred diagonal, so a load square to the grid gives a response square to it.
        /// With <see cref="Six"/> every cell leans the same way and a body crushed straight down
        /// shears along the diagonal.
        /// </summary>
        SixMirrored = 2,
    }
}
