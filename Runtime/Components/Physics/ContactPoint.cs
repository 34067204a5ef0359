using System.Numerics;

namespace Fulcrum.Components
{
    /// <summary>One contact point of a <see cref="Collision"/>, seen from the receiving collider (Unity's ContactPoint).</summary>
    public struct ContactPoint
    {
        /// <summary>World position, metres.</summary>
        public Vector3 point;
        /// <summary>Unit world normal pointing from the other collider towards this one (as in Unity).</summary>
        public Vector3 normal;
        /// <summary>Signed distance between the surfaces: negative when they overlap, metres.</summary>
        public float separation;
        /// <summary>Impulse the solver applied to this collider's body at the point in the step, N s.</summary>
        public Vector3 impulse;
        /// <summary>The collider that receives the message.</summary>
        public Collider? thisCollider;
        /// <summary>The collider it touches.</summary>
        public Collider? otherCollider;
    }
}
