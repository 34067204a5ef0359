using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// A material point bound to the rest element that contains it: its position is
    /// sum_i Weights_i x_i over the element's vertices (barycentric coordinates of the rest
    /// point; D is -1 for a triangle).
    /// </summary>
    internal struct ProbeBinding
    {
        public int A, B, C, D;
        public Vector4 Weights;
    }
}
