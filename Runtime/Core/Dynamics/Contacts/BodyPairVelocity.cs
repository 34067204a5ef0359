using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The velocities of a constraint's two bodies while one pass solves its rows: read from the
    /// solver bodies before the rows, updated by each row in turn, written back after them.
    /// </summary>
    internal struct BodyPairVelocity
    {
        public Vector3 LinearA, AngularA, LinearB, AngularB;
    }
}
