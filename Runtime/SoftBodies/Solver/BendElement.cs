namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A dihedral bending element on an edge shared by two triangles: wing vertices
    /// <see cref="A"/> (triangle A, C, D) and <see cref="B"/> (triangle B, D, C), edge C-D,
    /// the rest angle and the compliance 1/k of the hinge, 1/(N m). 24 bytes.
    /// </summary>
    internal struct BendElement
    {
        public int A, B, C, D;
        public float RestAngle;
        public float Compliance;
    }
}
