using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// One Jacobian row of a contact along a unit direction d shared by the manifold (the
    /// normal or a tangent): J = [-d, -(rA x d), d, rB x d]. Keeps the angular parts, their
    /// images under the inverse inertias (the angular velocity change per unit impulse), the
    /// effective mass 1 / (J M^-1 J^T) and the accumulated impulse. 56 bytes.
    /// </summary>
    internal struct ContactRow
    {
        /// <summary>rA x d.</summary>
        public Vector3 AngularA;
        /// <summary>rB x d.</summary>
        public Vector3 AngularB;
        /// <summary>IA^-1 (rA x d).</summary>
        public Vector3 VelocityA;
        /// <summary>IB^-1 (rB x d).</summary>
        public Vector3 VelocityB;
        /// <summary>1 / K, or 0 where K vanishes (two fixed bodies): such a row never acts.</summary>
        public float EffectiveMass;
        /// <summary>Accumulated impulse along d, N s.</summary>
        public float Impulse;

        /// <summary>
        /// K = mA + mB + (rA x d) . IA^-1 (rA x d) + (rB x d) . IB^-1 (rB x d), the inverse of
        /// the mass the row sees; its inverse is guarded so a degenerate row stays inert.
        /// </summary>
        public void Setup(Vector3 rA, Vector3 rB, Vector3 d, float invMassA, in Mat3 invInertiaA, float invMassB, in Mat3 invInertiaB)
        {
            AngularA = Vector3.Cross(rA, d);
            AngularB = Vector3.Cross(rB, d);
            VelocityA = invInertiaA * AngularA;
            VelocityB = invInertiaB * AngularB;
            float k = invMassA + invMassB + Vector3.Dot(AngularA, VelocityA) + Vector3.Dot(AngularB, VelocityB);
            EffectiveMass = k > 1e-30f ? 1f / k : 0f;
        }

        /// <summary>J v: the speed of B's point relative to A's along d.</summary>
        public readonly float Velocity(Vector3 d, Vector3 vA, Vector3 wA, Vector3 vB, Vector3 wB) =>
            Vector3.Dot(d, vB - vA) + Vector3.Dot(AngularB, wB) - Vector3.Dot(AngularA, wA);
    }
}
