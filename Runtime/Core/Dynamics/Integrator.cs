using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// Semi-implicit (symplectic) Euler for rigid bodies: velocities first from forces, then
    /// positions from the new velocities. Rotation uses a splitting of the free rigid body
    /// that conserves angular momentum exactly, so gyroscopic effects (the intermediate-axis
    /// flip of a spinning box) appear without energy or momentum drift. Bodies free of
    /// constraints, and every body under <see cref="PgsSolver"/>, are integrated here;
    /// <see cref="TgsSolver"/> integrates its bodies per substep itself.
    /// </summary>
    public static class Integrator
    {
        /// <summary>
        /// v += dt (g s + F/m), w += dt I^-1 tau, then damping v /= (1 + c dt): the implicit
        /// (Pade) form of exponential decay, stable for any c dt.
        /// </summary>
        internal static void IntegrateVelocities(BodyStorage b, Vector3 gravity, float dt, float maxSpeed) =>
            IntegrateVelocities(b, b.Active, 0, b.ActiveCount, gravity, dt, maxSpeed);

        /// <summary>As above, for the body slots <paramref name="slots"/>[start .. start + count).</summary>
        internal static void IntegrateVelocities(BodyStorage b, int[] slots, int start, int count, Vector3 gravity, float dt, float maxSpeed)
        {
            for (int k = start, end = start + count; k < end; k++)
            {
                int i = slots[k];
                if (b.Type[i] != BodyType.Dynamic || !b.Awake[i]) continue;
                Vector3 v = b.LinearVelocity[i];
                Vector3 w = b.AngularVelocity[i];
                SubstepKick.Of(b, i, gravity, dt).Apply(maxSpeed, ref v, ref w);
                b.LinearVelocity[i] = v;
                b.AngularVelocity[i] = w;
            }
        }


        /// <summary>
        /// Caps |w| at <see cref="Limits.MaxAngularSpeed"/>, the centre's speed |v| at
        /// <paramref name="maxSpeed"/>, then |w| so that no point within <paramref name="radius"/>
        /// of the centre moves faster than <paramref name="maxSpeed"/> (|v| + |w| r &lt;= maxSpeed,
        /// a bound on |v + w x r|): the spin gets what the centre leaves of the cap. Lengths are taken
        /// in double when the float square overflows, so a velocity of 3e38 is clamped to the
        /// cap, not zeroed.
        /// </summary>
        internal static void ClampSpeed(float maxSpeed, float radius, ref Vector3 v, ref Vector3 w)
        {
            float w2 = w.LengthSquared();
            if (!(w2 <= Limits.MaxAngularSpeed * Limits.MaxAngularSpeed))
                w *= (float)(Limits.MaxAngularSpeed / Limits.Length(w));
            float v2 = v.LengthSquared();
            float vs;
            if (v2 <= maxSpeed * maxSpeed) vs = MathF.Sqrt(v2);
            else
            {
                // The centre above the cap: clamp it (the scale in double, as |v| may overflow float).
                v *= (float)(maxSpeed / Limits.Length(v));
                vs = maxSpeed;
            }
            if (!(radius > 0)) return;
            // Then the spin gets what is left of the cap at the body's farthest point.
            float ws = MathF.Sqrt(w.LengthSquared()) * radius;
            float left = maxSpeed - vs;
            if (ws > left) w *= left / ws;
        }

        /// <summary>
        /// x += v dt for the centre of mass; the rotation (and, through the gyroscopic terms,
        /// the angular velocity) advances by <see cref="RotateFreeBody"/>. Kinematic bodies
        /// rotate at constant angular velocity. Refreshes origin and world inertia.
        /// </summary>
        /// <summary>
        /// <see cref="ClampSpeed"/> for the dynamic bodies of slots [start, start + count): the
        /// velocities the solver left, before they move the bodies.
        /// </summary>
        internal static void ClampSpeeds(BodyStorage b, int[] slots, int start, int count, float maxSpeed)
        {
            for (int k = start, end = start + count; k < end; k++)
            {
                int i = slots[k];
                if (b.Type[i] != BodyType.Dynamic) continue;
                ClampSpeed(maxSpeed, b.Radius[i], ref b.LinearVelocity[i], ref b.AngularVelocity[i]);
            }
        }

        internal static void IntegratePositions(BodyStorage b, float dt) => IntegratePositions(b, b.Active, 0, b.ActiveCount, dt);

        /// <summary>As above, for the body slots <paramref name="slots"/>[start .. start + count).</summary>
        internal static void IntegratePositions(BodyStorage b, int[] slots, int start, int count, float dt)
        {
            for (int k = start, end = start + count; k < end; k++)
            {
                int i = slots[k];
                BodyType type = b.Type[i];
                if (type == BodyType.Static || !b.Awake[i]) continue;
                b.Center[i] += b.LinearVelocity[i] * dt;
                if (type == BodyType.Dynamic && (b.Locks[i] & AxisLocks.Angular) != 0)
                {
                    // Locked rotation axes: the body turns at its (allowed) angular velocity; the
                    // free-body splitting would turn the momentum onto the locked axes.
                    b.Rotation[i] = Rotation.Integrate(b.Rotation[i], b.AngularVelocity[i], dt);
                }
                else if (type == BodyType.Dynamic)
                {
                    Quaternion q = b.Rotation[i];
                    Vector3 w = b.AngularVelocity[i];
                    RotateFreeBody(ref q, ref w, b.InverseInertiaPrincipal[i], b.InertiaFrame[i], dt);
                    b.Rotation[i] = q;
                    b.AngularVelocity[i] = w;
                }
                else
                {
                    b.Rotation[i] = Rotation.Integrate(b.Rotation[i], b.AngularVelocity[i], dt);
                }
                b.SyncOriginFromCenter(i);
                b.UpdateWorldInertia(i);
            }
        }

        /// <summary>
        /// Advances a torque-free rigid body's orientation <paramref name="q"/> and world angular
        /// velocity <paramref name="w"/> by <paramref name="dt"/>, with the symmetric splitting of
        /// Dullweber, Leimkuhler and McLachlan (J. Chem. Phys. 107, 1997): the Hamiltonian
        /// H = sum L_i^2 / 2 I_i is split per principal axis; each part is an exact rotation
        /// about that axis (the body by +theta, the body-frame momentum L by -theta, theta =
        /// L_i dt / I_i), applied in the order x/2, y/2, z, y/2, x/2. World angular momentum is
        /// conserved to round-off and the energy error stays bounded (the method is symplectic).
        /// Bodies with equal principal moments skip the splitting: w is then constant.
        /// </summary>
        /// <param name="q">Body orientation, updated.</param>
        /// <param name="w">World angular velocity, updated.</param>
        /// <param name="inverseInertia">1/I along the principal axes; 0 on a locked axis.</param>
        /// <param name="inertiaFrame">Principal axes in the body frame.</param>
        /// <param name="dt">Time step, s.</param>
        public static void RotateFreeBody(ref Quaternion q, ref Vector3 w, Vector3 inverseInertia, Quaternion inertiaFrame, float dt)
        {
            Vector3 ii = inverseInertia;
            if (ii.X == ii.Y && ii.Y == ii.Z)
            {
                q = Rotation.Integrate(q, w, dt);
                return;
            }
            Quaternion frame = q * inertiaFrame;                       // principal frame -> world
            Vector3 wp = Vector3.Transform(w, Quaternion.Conjugate(frame));
            Vector3 l = new Vector3(
                ii.X > 0 ? wp.X / ii.X : 0,
                ii.Y > 0 ? wp.Y / ii.Y : 0,
                ii.Z > 0 ? wp.Z / ii.Z : 0);
            // The splitting's energy error grows with the turn per step about each axis: fine
            // for a tenth of a radian, but a capsule turning 2 rad per step about a wide axis had
            // its momentum moved onto its long (light) axis and spun from 131 to 866 rad/s, 40
            // times the energy, in one step (WorldFuzz seed 887). A body turning more than
            // MaxFreeTurn about any principal axis takes the step in equal parts (a thin rod
            // tumbling at 2 rad per step then keeps its energy within 4 %); one part (the same
            // arithmetic as before) for every slower body.
            float turn = MathF.Max(MathF.Abs(l.X * ii.X), MathF.Max(MathF.Abs(l.Y * ii.Y), MathF.Abs(l.Z * ii.Z))) * dt;
            int parts = turn > MaxFreeTurn ? (int)MathF.Min(MathF.Ceiling(turn / MaxFreeTurn), MaxFreeParts) : 1;
            float step = parts == 1 ? dt : dt / parts;
            float h = 0.5f * step;
            for (int p = 0; p < parts; p++)
            {
                FreeAxisFlow(0, h, ii, ref frame, ref l);
                FreeAxisFlow(1, h, ii, ref frame, ref l);
                FreeAxisFlow(2, step, ii, ref frame, ref l);
                FreeAxisFlow(1, h, ii, ref frame, ref l);
                FreeAxisFlow(0, h, ii, ref frame, ref l);
            }
            frame = Quaternion.Normalize(frame);
            w = Vector3.Transform(l * ii, frame);
            q = Quaternion.Normalize(frame * Quaternion.Conjugate(inertiaFrame));
        }

        /// <summary>Largest turn about a principal axis, rad, that <see cref="RotateFreeBody"/> takes in one splitting step.</summary>
        internal const float MaxFreeTurn = 0.1f;

        /// <summary>Most splitting steps per call (25.6 rad per step in parts of 0.1; faster turns take larger parts).</summary>
        internal const int MaxFreeParts = 256;

        // The exact flow of H_i = L_i^2 / (2 I_i): L_i is constant, the body turns about axis i
        // at rate L_i / I_i, and the body-frame momentum turns the other way.
        static void FreeAxisFlow(int axis, float dt, Vector3 ii, ref Quaternion frame, ref Vector3 l)
        {
            float rate = axis == 0 ? l.X * ii.X : axis == 1 ? l.Y * ii.Y : l.Z * ii.Z;
            float theta = rate * dt;
            if (theta == 0) return;
            frame *= Rotation.AboutAxis(axis, theta);
            float c = MathF.Cos(theta), s = MathF.Sin(theta);
            // Rotate l by -theta about the axis.
            switch (axis)
            {
                case 0: l = new Vector3(l.X, c * l.Y + s * l.Z, -s * l.Y + c * l.Z); break;
                case 1: l = new Vector3(c * l.X - s * l.Z, l.Y, s * l.X + c * l.Z); break;
                default: l = new Vector3(c * l.X + s * l.Y, -s * l.X + c * l.Y, l.Z); break;
            }
        }
    }
}
