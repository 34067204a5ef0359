using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// What the normal rows of one contact share in a pass: the normal, the bodies' inverse
    /// masses, the constraint's softness, and the bodies' motion since the step began (the
    /// closing of their centres along the normal and their rotations), from which each point's
    /// current separation follows (see <see cref="ContactSolver"/>).
    /// </summary>
    internal readonly struct ContactPairMotion
    {
        public readonly Vector3 Normal;
        public readonly Vector3 InvMassA, InvMassB;
        /// <summary>n . (dpB - dpA), m.</summary>
        public readonly float Drift;
        public readonly Vector3 DThetaA, DThetaB;
        public readonly Softness Softness;

        public ContactPairMotion(Vector3 normal, Vector3 invMassA, Vector3 invMassB, float drift, Vector3 dThetaA, Vector3 dThetaB, in Softness softness)
        {
            Normal = normal;
            InvMassA = invMassA;
            InvMassB = invMassB;
            Drift = drift;
            DThetaA = dThetaA;
            DThetaB = dThetaB;
            Softness = softness;
        }
    }
}
