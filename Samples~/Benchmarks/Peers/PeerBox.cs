using System.Numerics;

namespace Fulcrum.Benchmarks.Peers
{
    /// <summary>One box of a peer scene: centre, rotation and half extents (metres).</summary>
    public readonly struct PeerBox
    {
        public readonly Vector3 Center;
        public readonly Quaternion Rotation;
        public readonly Vector3 HalfExtents;

        public PeerBox(Vector3 center, Quaternion rotation, Vector3 halfExtents)
        {
            Center = center;
            Rotation = rotation;
            HalfExtents = halfExtents;
        }

        /// <summary>Height of the box's lowest corner, for the ground-penetration figure.</summary>
        public static float LowestY(Vector3 center, Quaternion rotation, Vector3 halfExtents)
        {
            // A box's vertical reach is the sum over its axes of |axis.y| times the half extent.
            float reach = System.MathF.Abs(Vector3.Transform(Vector3.UnitX, rotation).Y) * halfExtents.X
                        + System.MathF.Abs(Vector3.Transform(Vector3.UnitY, rotation).Y) * halfExtents.Y
                        + System.MathF.Abs(Vector3.Transform(Vector3.UnitZ, rotation).Y) * halfExtents.Z;
            return center.Y - reach;
        }
    }
}
