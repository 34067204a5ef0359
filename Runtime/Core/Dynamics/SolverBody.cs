using System.Numerics;
using System.Runtime.InteropServices;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The solver's per-step copy of one body that takes part in constraints: everything a
    /// constraint row reads or writes, so that solving a constraint touches two of these and
    /// nothing else. 96 bytes (checked by a test). Slot 0 of the solver's body array is the
    /// fixed body that every static body maps to: zero inverse mass, zero velocity.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct SolverBody
    {
        /// <summary>Velocity of the centre of mass, m/s.</summary>
        public Vector3 LinearVelocity;
        /// <summary>1/m; 0 for static and kinematic bodies.</summary>
        public float InverseMass;
        /// <summary>World angular velocity, rad/s.</summary>
        public Vector3 AngularVelocity;
        /// <summary>
        /// Non-zero for dynamic bodies: only those are written back by the constraints. Bit 0 is
        /// set for every dynamic body; bits 1-6 carry its <see cref="AxisLocks"/>, so a body
        /// without locks has exactly 1 and the lock checks cost a compare.
        /// </summary>
        public int IsDynamic;
        /// <summary>World inverse inertia, frozen for the step.</summary>
        public Mat3 InverseInertia;
        /// <summary>Displacement of the centre of mass since the start of the step, m.</summary>
        public Vector3 DeltaPosition;
        /// <summary>Rotation since the start of the step (world frame, applied on the left).</summary>
        public Quaternion DeltaRotation;

        /// <summary>The <see cref="IsDynamic"/> value of a dynamic body with <paramref name="locks"/>.</summary>
        public static int DynamicFlags(AxisLocks locks) => 1 | ((int)locks << 1);

        /// <summary>The body's axis locks (None for fixed bodies).</summary>
        public readonly AxisLocks Locks => (AxisLocks)(IsDynamic >> 1);

        /// <summary>Whether some translation axis is locked: the inverse mass is then per axis.</summary>
        public readonly bool HasLinearLocks => (IsDynamic & ((int)AxisLocks.Linear << 1)) != 0;

        /// <summary>The per-axis inverse mass: 1/m on the free axes, 0 on the locked ones.</summary>
        public readonly Vector3 LinearInverseMass =>
            HasLinearLocks ? InverseMass * AxisLockMath.LinearMask(Locks) : new Vector3(InverseMass);

        /// <summary>d . M^-1 d for a unit direction d (the scalar inverse mass without locks).</summary>
        public readonly float InverseMassAlong(Vector3 d) =>
            HasLinearLocks ? Vector3.Dot(LinearInverseMass, d * d) : InverseMass;

        /// <summary>
        /// The small-angle rotation vector of <see cref="DeltaRotation"/> (2 x its vector part),
        /// enough to update contact separations within one step where the rotation is small.
        /// </summary>
        public readonly Vector3 DeltaAngle
        {
            get
            {
                Quaternion q = DeltaRotation;
                float s = q.W < 0 ? -2f : 2f;
                return new Vector3(q.X * s, q.Y * s, q.Z * s);
            }
        }

        /// <summary>Rotates <paramref name="v"/> by the step's rotation so far.</summary>
        public readonly Vector3 RotateByDelta(Vector3 v) => Vector3.Transform(v, DeltaRotation);

        /// <summary>Velocity of the material point at arm <paramref name="r"/> from the centre of mass.</summary>
        public readonly Vector3 PointVelocity(Vector3 r) => LinearVelocity + Vector3.Cross(AngularVelocity, r);

        /// <summary>
        /// Applies the impulse <paramref name="p"/> at arm <paramref name="r"/> to the velocities:
        /// v += P/m, w += I^-1 (r x P).
        /// </summary>
        public void ApplyImpulse(Vector3 r, Vector3 p)
        {
            LinearVelocity += InverseMass * (IsDynamic > 1 ? AxisLockMath.MaskLinear(p, Locks) : p);
            AngularVelocity += InverseInertia * Vector3.Cross(r, p);
        }

        /// <summary>Applies an angular impulse (N m s): w += I^-1 L.</summary>
        public void ApplyAngularImpulse(Vector3 l) => AngularVelocity += InverseInertia * l;

        /// <summary>
        /// Moves the body as an impulse <paramref name="p"/> at arm <paramref name="r"/> would over
        /// one unit of time (the position-level "pseudo impulse" of non-linear Gauss-Seidel).
        /// </summary>
        public void ApplyPositionImpulse(Vector3 r, Vector3 p)
        {
            DeltaPosition += InverseMass * (IsDynamic > 1 ? AxisLockMath.MaskLinear(p, Locks) : p);
            Rotate(InverseInertia * Vector3.Cross(r, p));
        }

        /// <summary>
        /// Stores velocities a solver worked on in local copies; only a dynamic body takes them
        /// (a static or kinematic body's velocities are the solver's input, never its output).
        /// </summary>
        public void StoreVelocities(Vector3 linear, Vector3 angular)
        {
            if (IsDynamic == 0) return;
            LinearVelocity = linear;
            AngularVelocity = angular;
        }

        /// <summary>Turns the body by the rotation vector <paramref name="angle"/> (rad), world axes.</summary>
        public void Rotate(Vector3 angle)
        {
            if (angle == Vector3.Zero) return;
            DeltaRotation = Quaternion.Normalize(Rotation.FromRotationVector(angle) * DeltaRotation);
        }
    }
}
