using System.Numerics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// A dynamic body's velocity update over one (sub)step, and what a TGS substep's position
    /// update reads: the one velocity integration of the free bodies (<see cref="Integrator"/>)
    /// and of the TGS substeps, which gather it once per step (<see cref="SolverContext.Prepare"/>)
    /// from the body storage's slot-indexed columns and then stream over these in solver order
    /// (reading eight columns of the body's slot per substep was a cache miss each in a large
    /// pile: the solver orders bodies by constraints, not by slot).
    /// </summary>
    internal struct SubstepKick
    {
        /// <summary>h (g s + F / m): gravity and force over the substep, m/s.</summary>
        public Vector3 Linear;
        /// <summary>Distance from the centre of mass to the farthest shape point, m (the speed cap's lever).</summary>
        public float Radius;
        /// <summary>h I⁻¹ τ with the world inverse inertia of the step's start, rad/s.</summary>
        public Vector3 Angular;
        /// <summary>1 / (1 + h c) for linear damping c; 1 without damping.</summary>
        public float LinearDamping;
        /// <summary>1 / (1 + h c) for angular damping c; 1 without damping.</summary>
        public float AngularDamping;
        /// <summary>The body's locked axes.</summary>
        public AxisLocks Locks;
        /// <summary>Equal principal moments: the body turns at its angular velocity (no free-body splitting).</summary>
        public bool Isotropic;

        /// <summary>The update of body slot <paramref name="i"/> for substeps of <paramref name="h"/> seconds.</summary>
        public static SubstepKick Of(BodyStorage b, int i, Vector3 gravity, float h)
        {
            Vector3 ii = b.InverseInertiaPrincipal[i];
            return new SubstepKick
            {
                Linear = h * (gravity * b.GravityScale[i] + b.Force[i] * b.InverseMass[i]),
                Angular = h * (b.InverseInertiaWorld[i] * b.Torque[i]),
                LinearDamping = b.LinearDamping[i] > 0 ? 1f / (1f + h * b.LinearDamping[i]) : 1f,
                AngularDamping = b.AngularDamping[i] > 0 ? 1f / (1f + h * b.AngularDamping[i]) : 1f,
                Locks = b.Locks[i],
                Radius = b.Radius[i],
                Isotropic = ii.X == ii.Y && ii.Y == ii.Z,
            };
        }

        /// <summary>
        /// v += h (g s + F/m), w += h I⁻¹ τ, damping v /= (1 + c h) (the implicit, Padé form of
        /// exponential decay, stable for any c h), axis locks (gravity and forces along a locked
        /// axis do nothing; a velocity set along one is dropped before it moves the body), then
        /// the speed cap.
        /// </summary>
        public readonly void Apply(float maxSpeed, ref Vector3 v, ref Vector3 w)
        {
            v += Linear;
            w += Angular;
            // A factor of exactly 1 leaves the bits unchanged, so skipping it is the same.
            if (LinearDamping != 1f) v *= LinearDamping;
            if (AngularDamping != 1f) w *= AngularDamping;
            if (Locks != AxisLocks.None)
            {
                v = AxisLockMath.MaskLinear(v, Locks);
                w = AxisLockMath.MaskAngular(w, Locks);
            }
            Integrator.ClampSpeed(maxSpeed, Radius, ref v, ref w);
        }
    }
}
