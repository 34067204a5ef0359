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
    }
}
