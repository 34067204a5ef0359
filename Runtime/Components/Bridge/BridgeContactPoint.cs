using System.Numerics;

namespace Fulcrum.Components
{
    /// <summary>One point of a bridged contact's manifolds, from <see cref="PhysicsBridge.GetPoints"/>.</summary>
    public struct BridgeContactPoint
    {
        /// <summary>World position, midway between the surfaces, metres.</summary>
        public Vector3 Position;
        /// <summary>Unit normal from A to B of the point's manifold.</summary>
        public Vector3 Normal;
        /// <summary>Signed distance between the surfaces (negative = overlap), metres.</summary>
        public float Separation;
        /// <summary>Normal impulse the solver applied at the point in the step, N s.</summary>
        public float NormalImpulse;
    }
}
