using System.Numerics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// The body's rigid motion over the substep, taken out of the stiffness-proportional damping.
    /// Rayleigh damping tau K(x) v damps deformation only where K annihilates rigid motion, and
    /// the tangent of a stressed body does not: its geometric (stress) part turns with the body,
    /// so K(x) applied to a finite rotation x - x_n is not zero. With the whole lag damped, a free
    /// Newton cube spinning at 1 rad/s lost half its angular momentum in 20 steps at the default
    /// tau = 0.01 s, and gained sixfold in 40 with 4 Newton iterations; a Newton body resting on
    /// another soft body had its rocking pumped up until it was thrown off. The damping now
    /// acts on x - x_n less the rigid motion that fits it best (<see cref="RigidFit"/>), applied
    /// as a finite rotation.
    /// </summary>
    internal sealed partial class ImplicitNewtonSolver
    {
        Vector3 _rigidShift, _rigidCentre;
        Quaternion _rigidTurn = Quaternion.Identity;

        /// <summary>Fits the rigid motion from <paramref name="start"/> to <paramref name="x"/> (see the class summary); leaves x - start in _lag.</summary>
        void FitRigidMotion(SoftBody body, Vector3[] x, Vector3[] start)
        {
            for (int i = 0; i < _n; i++) _lag[i] = x[i] - start[i];
            RigidFit.Fit(start, _lag, body.M, null, _n, out _rigidCentre, out _rigidShift, out Vector3 spin);
            float angle = spin.Length();
            _rigidTurn = angle > 0f ? Quaternion.CreateFromAxisAngle(spin / angle, angle) : Quaternion.Identity;
        }

        /// <summary>Where the fitted rigid motion takes the point that was at <paramref name="start"/>, less <paramref name="start"/>.</summary>
        Vector3 RigidDisplacement(Vector3 start) =>
            _rigidShift + Vector3.Transform(start - _rigidCentre, _rigidTurn) - (start - _rigidCentre);
    }
}
