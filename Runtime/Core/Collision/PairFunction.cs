using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Computes the contact of two shapes at world poses into <paramref name="output"/>
    /// (patches with normals from A to B, points within <see cref="ContactBuffer.Speculative"/>).
    /// Stateless: the same input always gives the same points and feature ids.
    /// </summary>
    internal delegate void PairFunction(in ShapeGeometry a, in Pose poseA, in ShapeGeometry b, in Pose poseB, ContactBuffer output);
}
