using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Two sets of buffers for clipping a box face (4 vertices) against 4 side planes (at most
    /// 8 vertices), and the planes. Owned by a <see cref="ContactBuffer"/>, so one per thread;
    /// reused because per-call stack buffers cost their zeroing on every pair.
    /// </summary>
    internal sealed class ClipScratch
    {
        public const int Capacity = 8;
        public readonly Vector3[] Points = new Vector3[Capacity], OtherPoints = new Vector3[Capacity];
        public readonly uint[] Keys = new uint[Capacity], OtherKeys = new uint[Capacity];
        public readonly uint[] Segments = new uint[Capacity], OtherSegments = new uint[Capacity];
        public readonly Vector3[] PlaneNormals = new Vector3[4];
        public readonly float[] PlaneOffsets = new float[4];
    }
}
