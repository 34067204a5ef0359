using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        /// <summary>
        /// Creates a body. Every field of <paramref name="def"/> is checked before anything
        /// changes; a bad one throws an <see cref="ArgumentException"/> naming it.
        /// </summary>
        public BodyHandle CreateBody(in BodyDef def)
        {
            ThrowIfInStep();
            if (def.Type != BodyType.Static && def.Type != BodyType.Kinematic && def.Type != BodyType.Dynamic)
                throw new ArgumentException($"body.Type must be Static, Kinematic or Dynamic, got {def.Type}.", nameof(def));
            Limits.CheckPosition(def.Position, "body.Position");
            Quaternion rotation = Validate.Rotation(def.Rotation, "body.Rotation");
            Limits.CheckSpeed(def.LinearVelocity, "body.LinearVelocity");
            Limits.CheckSpeed(def.AngularVelocity, "body.AngularVelocity");
            Validate.NonNegative(def.LinearDamping, "body.LinearDamping");
            Validate.NonNegative(def.AngularDamping, "body.AngularDamping");
            Limits.CheckGravityScale(def.GravityScale, "body.GravityScale");
            if (def.Mass != 0) Limits.CheckMass(def.Mass, "body.Mass");
            CheckAxisLocks(def.Locks, "body.Locks");

            BodyStorage b = Bodies;
            int i = b.Allocate();
            b.Type[i] = def.Type;
            b.Position[i] = def.Position;
            b.Rotation[i] = rotation;
            b.PreviousPosition[i] = def.Position;
            b.PreviousRotation[i] = rotation;
            bool moves = def.Type != BodyType.Static;
            b.Locks[i] = def.Locks;
            // A dynamic body starts without motion along its locked axes.
            AxisLocks locks = def.Type == BodyType.Dynamic ? def.Locks : AxisLocks.None;
            b.LinearVelocity[i] = moves ? Dynamics.AxisLockMath.MaskLinear(def.LinearVelocity, locks) : default;
            b.AngularVelocity[i] = moves ? Dynamics.AxisLockMath.MaskAngular(def.AngularVelocity, locks) : default;
            b.Force[i] = default;
            b.Torque[i] = default;
            b.LinearDamping[i] = def.LinearDamping;
            b.AngularDamping[i] = def.AngularDamping;
            b.GravityScale[i] = def.GravityScale;
            b.MassOverride[i] = def.Mass;
            b.AllowSleep[i] = def.AllowSleep;
            b.Awake[i] = def.Type != BodyType.Static && (def.IsAwake || !def.AllowSleep);
            b.Ccd[i] = def.Ccd;
            b.SleepTime[i] = 0;
            b.HasKinematicTarget[i] = false;
            b.VelocityFromTarget[i] = false;
            b.FirstShape[i] = -1;
            b.Name[i] = def.Name;
            b.UserData[i] = def.UserData;
            UpdateMassProperties(i);
            return new BodyHandle(i, b.Generation[i], Id);
        }

        /// <summary>
        /// Removes a body with its shapes (and the joints and contacts that name it). The
        /// handle goes stale; removing it again throws <see cref="StaleHandleException"/>.
        /// </summary>
        public void DestroyBody(BodyHandle body)
        {
            ThrowIfInStep();
            int i = Slot(body);
            OnBodyDestroyed(i);
            int s = Bodies.FirstShape[i];
            while (s >= 0)
            {
                int next = Shapes.NextInBody[s];
                ReleaseShape(s);
                s = next;
            }
            Bodies.FirstShape[i] = -1;
            Bodies.Release(i);
        }

        /// <summary>True when the handle names a live body of this world.</summary>
        public bool IsValid(BodyHandle body) => body.WorldId == Id && Bodies.IsLive(body);

        /// <summary>A view for reading and writing one body; throws if the handle is stale.</summary>
        public BodyRef GetBody(BodyHandle body) => new BodyRef(this, Slot(body), body.Generation);

        /// <summary>Copies the handles of all live bodies into <paramref name="into"/>; returns how many (at most its length).</summary>
        public int GetBodies(Span<BodyHandle> into)
        {
            int n = Math.Min(into.Length, Bodies.ActiveCount);
            for (int k = 0; k < n; k++)
            {
                int i = Bodies.Active[k];
                into[k] = new BodyHandle(i, Bodies.Generation[i], Id);
            }
            return n;
        }

        /// <summary>The slot of a live body, or <see cref="StaleHandleException"/>.</summary>
        internal int Slot(BodyHandle body) => LiveSlot(body.Id, Bodies.Slots, nameof(BodyHandle), "body", "destroyed");

        /// <summary>
        /// Sets mass, centre and inertia directly, overriding the shapes' densities until
        /// <see cref="ResetMassProperties"/>. Dynamic bodies only; checked before anything changes.
        /// </summary>
        public void SetMassProperties(BodyHandle body, in MassProperties mass)
        {
            ThrowIfInStep();
            int i = Slot(body);
            mass.Validate("mass");
            Limits.CheckMass(mass.Mass, "mass.Mass");
            Limits.CheckPosition(mass.Center, "mass.Center");
            if (Bodies.Type[i] != BodyType.Dynamic) throw new InvalidOperationException($"{Describe(i)} is not dynamic: only dynamic bodies have mass.");
            ApplyMass(i, mass);
            Bodies.MassOverride[i] = -1; // explicit distribution: shapes no longer decide
            UpdateRadius(i);
        }

        /// <summary>Returns to mass properties computed from the shapes' densities.</summary>
        public void ResetMassProperties(BodyHandle body)
        {
            ThrowIfInStep();
            int i = Slot(body);
            Bodies.MassOverride[i] = 0;
            UpdateMassProperties(i);
        }

        /// <summary>Mass properties of a body's shapes at their densities (before any override).</summary>
        public MassProperties ComputeShapeMass(BodyHandle body) => ShapeMass(Slot(body));

        MassProperties ShapeMass(int i)
        {
            MassProperties total = default;
            for (int s = Bodies.FirstShape[i]; s >= 0; s = Shapes.NextInBody[s])
            {
                if (Shapes.IsSensor[s] || Shapes.Density[s] <= 0) continue;
                MassProperties m = Shapes.Geometry[s].ComputeMass(Shapes.Density[s]).Transformed(Shapes.LocalPose[s]);
                total = total.Mass > 0 ? MassProperties.Combine(total, m) : m;
            }
            return total;
        }

        // Recomputes mass from the shapes (or the mass override) after a shape or type change.
        // A dynamic body with no massive shape gets 1 kg and unit inertia, so it still moves.
        internal void UpdateMassProperties(int i)
        {
            BodyStorage b = Bodies;
            if (b.Type[i] != BodyType.Dynamic)
            {
                b.Mass[i] = 0;
                b.InverseMass[i] = 0;
                b.LocalCenter[i] = Vector3.Zero;
                b.InertiaLocal[i] = default;
                b.InverseInertiaPrincipal[i] = Vector3.Zero;
                b.InertiaFrame[i] = Quaternion.Identity;
                b.SyncCenterFromOrigin(i);
                b.InverseInertiaWorld[i] = default;
                return;
            }
            if (b.MassOverride[i] >= 0) // else set explicitly
            {
                MassProperties m = ShapeMass(i);
                if (!(m.Mass > 0)) m = new MassProperties(1f, Vector3.Zero, Mat3.Identity);
                if (b.MassOverride[i] > 0) m = m.WithMass(b.MassOverride[i]);
                ApplyMass(i, m);
            }
            UpdateRadius(i);
        }

        // The farthest point of the body's shapes (their local bounds' corners) from the centre
        // of mass: with it the integrator caps spin so that no point outruns MaxLinearSpeed.
        void UpdateRadius(int i)
        {
            float r2 = 0;
            Vector3 c = Bodies.LocalCenter[i];
            for (int s = Bodies.FirstShape[i]; s >= 0; s = Shapes.NextInBody[s])
            {
                if (Shapes.Geometry[s].IsStaticOnly) continue;
                Aabb box = Shapes.Geometry[s].ComputeAabb(Shapes.LocalPose[s]);
                Vector3 far = Vector3.Max(Vector3.Abs(box.Min - c), Vector3.Abs(box.Max - c));
                r2 = MathF.Max(r2, far.LengthSquared());
            }
            Bodies.Radius[i] = MathF.Sqrt(r2);
        }

        void ApplyMass(int i, in MassProperties m)
        {
            BodyStorage b = Bodies;
            b.Mass[i] = m.Mass;
            b.InverseMass[i] = 1f / m.Mass;
            b.LocalCenter[i] = m.Center;
            b.InertiaLocal[i] = m.Inertia;
            Vector3 moments = Mathematics.Rotation.Diagonalize(m.Inertia, out Quaternion axes);
            b.InertiaFrame[i] = axes;
            b.InverseInertiaPrincipal[i] = new Vector3(
                moments.X > 0 ? 1f / moments.X : 0,
                moments.Y > 0 ? 1f / moments.Y : 0,
                moments.Z > 0 ? 1f / moments.Z : 0);
            b.SyncCenterFromOrigin(i);
            b.UpdateWorldInertia(i);
        }

        internal string Describe(int i) => Bodies.Name[i] is string n ? $"body '{n}'" : $"body {i}";

        /// <summary>
        /// Applies a force (or acceleration, impulse, velocity change) at the centre of mass.
        /// Dynamic bodies only; on static and kinematic bodies it does nothing, as in Unity.
        /// Wakes the body.
        /// </summary>
        public void AddForce(BodyHandle body, Vector3 force, ForceMode mode = ForceMode.Force) =>
            PushAtCentre(body, force, mode, angular: false, nameof(force));

        /// <summary>
        /// Applies a force at a world point: the force at the centre of mass plus the torque
        /// (p - c) x F. Dynamic bodies only. Wakes the body.
        /// </summary>
        public void AddForceAtPosition(BodyHandle body, Vector3 force, Vector3 worldPoint, ForceMode mode = ForceMode.Force)
        {
            int i = Slot(body);
            Limits.CheckForce(force, nameof(force));
            Limits.CheckPosition(worldPoint, nameof(worldPoint));
            ThrowIfInStep();
            Vector3 torque = Vector3.Cross(worldPoint - Bodies.Center[i], force);
            Limits.CheckForce(torque, nameof(worldPoint));
            if (Bodies.Type[i] != BodyType.Dynamic) return;
            BodyPush linear = LinearPush(i, force, mode), angular = AngularPush(i, torque, mode);
            linear.Check(nameof(force));
            angular.Check(nameof(force));
            linear.Apply(i);
            angular.Apply(i);
            Wake(i);
        }

        /// <summary>Applies a torque (or angular acceleration, impulse, velocity change) in world axes. Dynamic bodies only. Wakes the body.</summary>
        public void AddTorque(BodyHandle body, Vector3 torque, ForceMode mode = ForceMode.Force) =>
            PushAtCentre(body, torque, mode, angular: true, nameof(torque));

        // AddForce and AddTorque: the same checks and order (handle, size, not inside a step; a
        // non-dynamic body ignores it), one push, linear or angular, checked before it lands.
        void PushAtCentre(BodyHandle body, Vector3 value, ForceMode mode, bool angular, string name)
        {
            int i = Slot(body);
            Limits.CheckForce(value, name);
            ThrowIfInStep();
            if (Bodies.Type[i] != BodyType.Dynamic) return;
            BodyPush push = angular ? AngularPush(i, value, mode) : LinearPush(i, value, mode);
            push.Check(name);
            push.Apply(i);
            Wake(i);
        }

        // What a push at the centre of mass of dynamic body i leaves: the force accumulated for
        // the step (force, acceleration) or the velocity (impulse, velocity change).
        BodyPush LinearPush(int i, Vector3 f, ForceMode mode)
        {
            BodyStorage b = Bodies;
            return mode switch
            {
                ForceMode.Force => new BodyPush(b.Force, b.Force[i] + f, Limits.MaxForce, "the force accumulated this step"),
                ForceMode.Acceleration => new BodyPush(b.Force, b.Force[i] + f * b.Mass[i], Limits.MaxForce, "mass x acceleration accumulated this step"),
                ForceMode.Impulse => new BodyPush(b.LinearVelocity, b.LinearVelocity[i] + f * b.InverseMass[i], Limits.MaxInputSpeed, "the velocity after the impulse"),
                ForceMode.VelocityChange => new BodyPush(b.LinearVelocity, b.LinearVelocity[i] + f, Limits.MaxInputSpeed, "the velocity after the change"),
                _ => throw new ArgumentException($"Unknown ForceMode {mode}.", nameof(mode)),
            };
        }

        // The same for a turning push: the torque accumulated for the step or the angular velocity.
        BodyPush AngularPush(int i, Vector3 t, ForceMode mode)
        {
            BodyStorage b = Bodies;
            return mode switch
            {
                ForceMode.Force => new BodyPush(b.Torque, b.Torque[i] + t, Limits.MaxForce, "the torque accumulated this step"),
                ForceMode.Acceleration => new BodyPush(b.Torque, b.Torque[i] + WorldInertia(i) * t, Limits.MaxForce, "inertia x angular acceleration accumulated this step"),
                ForceMode.Impulse => new BodyPush(b.AngularVelocity, b.AngularVelocity[i] + b.InverseInertiaWorld[i] * t, Limits.MaxInputSpeed, "the angular velocity after the impulse"),
                ForceMode.VelocityChange => new BodyPush(b.AngularVelocity, b.AngularVelocity[i] + t, Limits.MaxInputSpeed, "the angular velocity after the change"),
                _ => throw new ArgumentException($"Unknown ForceMode {mode}.", nameof(mode)),
            };
        }

        // The world inertia tensor R I R^T (for mass-independent angular acceleration).
        internal Mat3 WorldInertia(int i)
        {
            Mat3 r = Mat3.FromQuaternion(Bodies.Rotation[i]);
            return r * Bodies.InertiaLocal[i] * r.Transposed;
        }

        /// <summary>
        /// Drives a kinematic body to <paramref name="position"/>/<paramref name="rotation"/>
        /// over the next step: the step gives it the velocity that reaches the target, so it
        /// pushes dynamic bodies as a moving body should, and ends exactly on the target.
        /// Without a new target the following step stops it.
        /// </summary>
        public void SetKinematicTarget(BodyHandle body, Vector3 position, Quaternion rotation)
        {
            int i = Slot(body);
            Limits.CheckPosition(position, nameof(position));
            Quaternion q = Validate.Rotation(rotation, nameof(rotation));
            ThrowIfInStep();
            if (Bodies.Type[i] != BodyType.Kinematic)
                throw new InvalidOperationException($"{Describe(i)} is not kinematic: only kinematic bodies take a target pose.");
            // Keep the target on the same hemisphere as the current rotation (shortest arc).
            if (Quaternion.Dot(q, Bodies.Rotation[i]) < 0) q = Quaternion.Negate(q);
            Bodies.TargetPosition[i] = position;
            Bodies.TargetRotation[i] = q;
            Bodies.HasKinematicTarget[i] = true;
        }

        /// <summary>Wakes a body (and, once islands exist, its island).</summary>
        internal void Wake(int i)
        {
            if (Bodies.Type[i] == BodyType.Static) return;
            Bodies.Awake[i] = true;
            Bodies.SleepTime[i] = 0;
            WakeIsland(i);
        }

        /// <summary>
        /// The pose between the start and the end of the last step, for rendering between
        /// fixed steps: <paramref name="alpha"/> 0 is the previous pose, 1 the current one
        /// (see <see cref="FixedStepper.InterpolationFactor"/>).
        /// </summary>
        public Pose GetInterpolatedPose(BodyHandle body, float alpha)
        {
            int i = Slot(body);
            alpha = Math.Clamp(alpha, 0f, 1f);
            Vector3 p = Vector3.Lerp(Bodies.PreviousPosition[i], Bodies.Position[i], alpha);
            Quaternion q = Quaternion.Slerp(Bodies.PreviousRotation[i], Bodies.Rotation[i], alpha);
            return new Pose(p, q);
        }
    }
}
