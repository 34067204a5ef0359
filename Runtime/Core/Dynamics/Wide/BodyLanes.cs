#if NET
using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The bodies of a group in lanes: velocities, inverse masses and inertias, the dynamic
    /// flags and (for the separation update) the motion so far.
    /// </summary>
    internal struct BodyLanes
    {
        public WideVector3 VA, WA, VB, WB, DpA, DpB, DThetaA, DThetaB;
        public WideMatrix3 IA, IB;
        // The floats beside the velocities in SolverBody: the inverse mass and the dynamic
        // flag (an int), written back unchanged by the transposing scatter.
        public Vector<float> InvMassA, FlagA, InvMassB, FlagB;
    }
}
#endif
