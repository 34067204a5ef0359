#nullable enable
using UnityEngine;
using N = System.Numerics;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Conversions between Unity's vector types and System.Numerics, component for component
    /// (Fulcrum's scene files are right-handed and Unity is left-handed, but inside one program
    /// both are just y-up coordinates: the physics does not depend on handedness).
    /// Note: inside namespace Fulcrum, the name ForceMode means Fulcrum.ForceMode; Unity's is
    /// written in full.
    /// </summary>
    public static class UnityConversions
    {
        /// <summary>UnityEngine.Vector3 to System.Numerics.Vector3.</summary>
        public static N.Vector3 ToNumerics(this Vector3 v) => new N.Vector3(v.x, v.y, v.z);

        /// <summary>UnityEngine.Quaternion to System.Numerics.Quaternion.</summary>
        public static N.Quaternion ToNumerics(this Quaternion q) => new N.Quaternion(q.x, q.y, q.z, q.w);

        /// <summary>System.Numerics.Vector3 to UnityEngine.Vector3.</summary>
        public static Vector3 ToUnity(this N.Vector3 v) => new Vector3(v.X, v.Y, v.Z);

        /// <summary>System.Numerics.Quaternion to UnityEngine.Quaternion.</summary>
        public static Quaternion ToUnity(this N.Quaternion q) => new Quaternion(q.X, q.Y, q.Z, q.W);

        /// <summary>UnityEngine.ForceMode to Fulcrum.ForceMode (same four modes).</summary>
        public static Fulcrum.ForceMode ToFulcrum(this UnityEngine.ForceMode mode) => mode switch
        {
            UnityEngine.ForceMode.Acceleration => Fulcrum.ForceMode.Acceleration,
            UnityEngine.ForceMode.Impulse => Fulcrum.ForceMode.Impulse,
            UnityEngine.ForceMode.VelocityChange => Fulcrum.ForceMode.VelocityChange,
            _ => Fulcrum.ForceMode.Force,
        };
    }
}
