using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>A vertex held at a point fixed in a rigid body's frame (relative to the body origin).</summary>
    internal struct Attachment
    {
        public int Vertex;
        public int BodySlot;
        public int BodyGeneration;
        public Vector3 LocalAnchor;
    }
}
