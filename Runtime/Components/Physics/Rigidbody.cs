using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    /// <summary>
    /// Makes its entity a simulated body, with Unity's Rigidbody API. The colliders on the
    /// entity and on child entities without a Rigidbody of their own form its shape (a
    /// compound); their volumes give the centre of mass and the inertia, scaled to
    /// <see cref="mass"/>, as in Unity.
    /// Departures from Unity: no angular speed cap unless <see cref="maxAngularVelocity"/> is
    /// set (Unity's default is 7 rad/s), no sleepThreshold per body (see <see cref="WorldSettings"/>), constraints are enforced
    /// as <see cref="constraints"/> describes, and setting a property from inside
    /// <see cref="World.Step"/> (a Core callback) throws instead of corrupting the step.
    /// </summary>
    public sealed partial class Rigidbody : Component
    {
        BodyHandle _body;
        float _mass = 1f;
        float _linearDamping;
        float _angularDamping = 0.05f;
        bool _useGravity = true;
        bool _isKinematic;
        RigidbodyConstraints _constraints;
        CollisionDetectionMode _collisionDetectionMode;
        RigidbodyInterpolation _interpolation;
        Vector3? _centerOfMass;
        Vector3 _linearVelocity, _angularVelocity;
        internal readonly List<Collider> Colliders = new List<Collider>();

        // Host bookkeeping: the transform version last seen.
        internal long SeenTransformVersion;

        /// <summary>The body in <see cref="PhysicsScene.world"/>; None while the entity is inactive.</summary>
        public BodyHandle body => _body;

        internal bool HasBody => !_body.IsNone;

        World World => scene.world;

        /// <summary>Mass, kg (&gt; 0). Default: 1. Colliders' volumes only shape the distribution.</summary>
        public float mass
        {
            get => _mass;
            set
            {
                FieldCheck.Mass(value, this, nameof(mass));
                ThrowIfStepping(nameof(mass));
                _mass = value;
                if (HasBody) ApplyMass();
            }
        }

        /// <summary>Velocity of the centre of mass, m/s.</summary>
        public Vector3 linearVelocity
        {
            get => HasBody ? World.GetBody(_body).LinearVelocity : _linearVelocity;
            set
            {
                SetSpeed(ref _linearVelocity, value, nameof(linearVelocity));
                if (HasBody) World.GetBody(_body).LinearVelocity = value;
            }
        }

        /// <summary>World angular velocity, rad/s.</summary>
        public Vector3 angularVelocity
        {
            get => HasBody ? World.GetBody(_body).AngularVelocity : _angularVelocity;
            set
            {
                SetSpeed(ref _angularVelocity, value, nameof(angularVelocity));
                if (HasBody) World.GetBody(_body).AngularVelocity = value;
            }
        }

        // The head of the two velocity setters: a finite speed within the input limit, refused
        // mid-step, then stored; the caller then hands it to the live body.
        void SetSpeed(ref Vector3 field, Vector3 value, string member)
        {
            FieldCheck.Speed(value, this, member);
            ThrowIfStepping(member);
            field = value;
        }

        /// <summary>
        /// Kinematic bodies are moved by the game (<see cref="MovePosition"/>, or the transform)
        /// and push dynamic bodies without being pushed back. Default: false.
        /// </summary>
        public bool isKinematic
        {
            get => _isKinematic;
            set
            {
                if (!SetFlag(ref _isKinematic, value, nameof(isKinematic))) return;
                if (!HasBody) return;
                World.SetBodyType(_body, value ? BodyType.Kinematic : BodyType.Dynamic);
                ApplyMass();
                ValidateColliders();
            }
        }

        /// <summary>Whether world gravity acts on the body. Default: true.</summary>
        public bool useGravity
        {
            get => _useGravity;
            set
            {
                ThrowIfStepping(nameof(useGravity));
                _useGravity = value;
                if (HasBody) World.GetBody(_body).GravityScale = value ? 1f : 0f;
            }
        }

        /// <summary>Linear damping rate, 1/s (&gt;= 0); v decays as 1/(1 + c dt) per step. Default: 0 (Unity's drag).</summary>
        public float linearDamping
        {
            get => _linearDamping;
            set
            {
                SetNonNegative(ref _linearDamping, value, nameof(linearDamping));
                if (HasBody) World.GetBody(_body).LinearDamping = value;
            }
        }

        /// <summary>Angular damping rate, 1/s (&gt;= 0). Default: 0.05, as in Unity (angularDrag).</summary>
        public float angularDamping
        {
            get => _angularDamping;
            set
            {
                SetNonNegative(ref _angularDamping, value, nameof(angularDamping));
                if (HasBody) World.GetBody(_body).AngularDamping = value;
            }
        }

        /// <summary>
        /// Frozen degrees of freedom, in world axes: the core's <see cref="AxisLocks"/>
        /// (<see cref="BodyRef.Locks"/>), enforced inside the solver as PhysX does, so contacts
        /// and joints see the reduced mobility (a frozen axis has zero inverse mass, frozen
        /// rotation axes are projected out of the inverse inertia; FreezeRotation is infinite
        /// inertia). Frozen is exact: a frozen coordinate does not change at all.
        /// </summary>
        public RigidbodyConstraints constraints
        {
            get => _constraints;
            set
            {
                if (((int)value & ~(int)RigidbodyConstraints.FreezeAll) != 0)
                    throw new ArgumentException($"{this}: constraints has unknown bits 0x{(int)value:X}.", nameof(constraints));
                ThrowIfStepping(nameof(constraints));
                _constraints = value;
                if (HasBody) World.GetBody(_body).Locks = AxisLocksOf(value);
            }
        }

        /// <summary>Discrete or continuous (any continuous mode sets <see cref="BodyDef.Ccd"/>). Default: Discrete.</summary>
        public CollisionDetectionMode collisionDetectionMode
        {
            get => _collisionDetectionMode;
            set
            {
                if (value < CollisionDetectionMode.Discrete || value > CollisionDetectionMode.ContinuousSpeculative)
                    throw new ArgumentException($"{this}: collisionDetectionMode {value} is not a mode.", nameof(collisionDetectionMode));
                ThrowIfStepping(nameof(collisionDetectionMode));
                _collisionDetectionMode = value;
                if (HasBody) World.GetBody(_body).Ccd = value != CollisionDetectionMode.Discrete;
            }
        }

        /// <summary>How the transform shows the body between fixed steps. Default: None.</summary>
        public RigidbodyInterpolation interpolation
        {
            get => _interpolation;
            set
            {
                if (value < RigidbodyInterpolation.None || value > RigidbodyInterpolation.Extrapolate)
                    throw new ArgumentException($"{this}: interpolation {value} is not a mode.", nameof(interpolation));
                _interpolation = value;
            }
        }

        /// <summary>
        /// Centre of mass in the entity's frame, metres. Computed from the colliders unless set;
        /// setting it keeps the inertia tensor about the centre (as Unity does).
        /// </summary>
        public Vector3 centerOfMass
        {
            get => HasBody ? World.GetBody(_body).LocalCenterOfMass : _centerOfMass ?? Vector3.Zero;
            set
            {
                FieldCheck.Finite(value, this, "centerOfMass");
                ThrowIfStepping(nameof(centerOfMass));
                _centerOfMass = value;
                if (HasBody) ApplyMass();
            }
        }

        /// <summary>True while the centre of mass comes from the colliders (Unity's automaticCenterOfMass).</summary>
        public bool automaticCenterOfMass => _centerOfMass == null;

        /// <summary>Returns the centre of mass to the one computed from the colliders.</summary>
        public void ResetCenterOfMass()
        {
            ThrowIfStepping(nameof(centerOfMass));
            _centerOfMass = null;
            if (HasBody) ApplyMass();
        }

        /// <summary>World centre of mass, metres.</summary>
        public Vector3 worldCenterOfMass => HasBody ? World.GetBody(_body).CenterOfMass : transform.TransformPoint(centerOfMass);

        /// <summary>Inertia tensor about the centre of mass in the entity frame, kg m^2 (zero while inactive or kinematic).</summary>
        public Mat3 inertiaTensor => HasBody ? World.GetBody(_body).InertiaLocal : default;

        /// <summary>The body's position (the entity origin), metres. Setting it teleports the body.</summary>
        public Vector3 position
        {
            get => HasBody ? World.GetBody(_body).Position : transform.position;
            set
            {
                FieldCheck.Position(value, this, "position");
                ThrowIfStepping(nameof(position));
                if (!HasBody) { transform.position = value; return; }
                World.GetBody(_body).Position = value;
                WriteTransform(World.GetBody(_body).Pose);
            }
        }

        /// <summary>The body's rotation. Setting it teleports the body.</summary>
        public Quaternion rotation
        {
            get => HasBody ? World.GetBody(_body).Rotation : transform.rotation;
            set
            {
                Quaternion q = FieldCheck.Rotation(value, this, "rotation");
                ThrowIfStepping(nameof(rotation));
                if (!HasBody) { transform.rotation = q; return; }
                World.GetBody(_body).Rotation = q;
                WriteTransform(World.GetBody(_body).Pose);
            }
        }

        /// <summary>
        /// Applies a force at the centre of mass (world axes) with one of Unity's four modes:
        /// Force (N) and Acceleration (m/s^2) act over the next step; Impulse (N s) and
        /// VelocityChange (m/s) change the velocity at once. Nothing happens on a kinematic or
        /// inactive body, as in Unity.
        /// </summary>
        public void AddForce(Vector3 force, ForceMode mode = ForceMode.Force)
        {
            FieldCheck.Force(force, this, "force");
            ThrowIfStepping(nameof(AddForce));
            if (HasBody) World.AddForce(_body, force, mode);
        }

        /// <summary><see cref="AddForce(Vector3, ForceMode)"/> with the components given separately.</summary>
        public void AddForce(float x, float y, float z, ForceMode mode = ForceMode.Force) => AddForce(new Vector3(x, y, z), mode);

        /// <summary>Like <see cref="AddForce(Vector3, ForceMode)"/>, with the force in the body's axes.</summary>
        public void AddRelativeForce(Vector3 force, ForceMode mode = ForceMode.Force)
        {
            FieldCheck.Force(force, this, "force");
            AddForce(Vector3.Transform(force, rotation), mode);
        }

        /// <summary>Applies a torque in world axes (N m, or rad/s^2, N m s, rad/s by mode).</summary>
        public void AddTorque(Vector3 torque, ForceMode mode = ForceMode.Force)
        {
            FieldCheck.Force(torque, this, "torque");
            ThrowIfStepping(nameof(AddTorque));
            if (HasBody) World.AddTorque(_body, torque, mode);
        }

        /// <summary>Like <see cref="AddTorque"/>, with the torque in the body's axes.</summary>
        public void AddRelativeTorque(Vector3 torque, ForceMode mode = ForceMode.Force)
        {
            FieldCheck.Force(torque, this, "torque");
            AddTorque(Vector3.Transform(torque, rotation), mode);
        }

        /// <summary>Applies a force at a world point: the force at the centre plus the torque (p - c) x F.</summary>
        public void AddForceAtPosition(Vector3 force, Vector3 position, ForceMode mode = ForceMode.Force)
        {
            FieldCheck.Force(force, this, "force");
            FieldCheck.Position(position, this, "position");
            ThrowIfStepping(nameof(AddForceAtPosition));
            if (HasBody) World.AddForceAtPosition(_body, force, position, mode);
        }

        /// <summary>Velocity of the body's material point at a world position, m/s.</summary>
        public Vector3 GetPointVelocity(Vector3 worldPoint) => HasBody ? World.GetBody(_body).GetPointVelocity(worldPoint) : Vector3.Zero;

        /// <summary>
        /// Moves the body to <paramref name="position"/> in the next step. A kinematic body gets
        /// the velocity that reaches it (<see cref="World.SetKinematicTarget"/>), so it pushes
        /// what it meets and interpolates smoothly; a dynamic body is teleported, as in Unity.
        /// </summary>
        public void MovePosition(Vector3 position)
        {
            FieldCheck.Position(position, this, "position");
            ThrowIfStepping(nameof(MovePosition));
            if (!HasBody) { transform.position = position; return; }
            if (!_isKinematic) { this.position = position; return; }
            BodyStorage b = World.Bodies;
            int i = _body.Index;
            World.SetKinematicTarget(_body, position, b.HasKinematicTarget[i] ? b.TargetRotation[i] : b.Rotation[i]);
        }

        /// <summary>Turns the body to <paramref name="rotation"/> in the next step (see <see cref="MovePosition"/>).</summary>
        public void MoveRotation(Quaternion rotation)
        {
            Quaternion q = FieldCheck.Rotation(rotation, this, "rotation");
            ThrowIfStepping(nameof(MoveRotation));
            if (!HasBody) { transform.rotation = q; return; }
            if (!_isKinematic) { this.rotation = q; return; }
            BodyStorage b = World.Bodies;
            int i = _body.Index;
            World.SetKinematicTarget(_body, b.HasKinematicTarget[i] ? b.TargetPosition[i] : b.Position[i], q);
        }

        /// <summary>Puts the body to sleep now: it stops (velocities zeroed) until something wakes it.</summary>
        public void Sleep()
        {
            ThrowIfStepping(nameof(Sleep));
            if (!HasBody) return;
            BodyStorage b = World.Bodies;
            int i = _body.Index;
            b.LinearVelocity[i] = default;
            b.AngularVelocity[i] = default;
            b.Awake[i] = false;
        }

        /// <summary>Wakes the body.</summary>
        public void WakeUp()
        {
            ThrowIfStepping(nameof(WakeUp));
            if (HasBody) World.GetBody(_body).WakeUp();
        }

        /// <summary>True while the body sleeps (or has no body because its entity is inactive).</summary>
        public bool IsSleeping() => !HasBody || !World.GetBody(_body).IsAwake;

        internal override void OnAdded()
        {
            if (entity.GetComponent<Rigidbody>() != this)
                throw new InvalidOperationException($"Entity '{name}' already has a Rigidbody: an entity carries at most one.");
            if (entity.GetComponent<SoftBody>() != null)
                throw new InvalidOperationException($"Entity '{name}' has a SoftBody: it cannot also carry a Rigidbody.");
        }

        internal override void Activate()
        {
            Pose pose = transform.WorldPose;
            BodyDef def = BodyDef.Default;
            def.Type = _isKinematic ? BodyType.Kinematic : BodyType.Dynamic;
            def.Position = pose.Position;
            def.Rotation = pose.Rotation;
            def.LinearVelocity = _linearVelocity;
            def.AngularVelocity = _angularVelocity;
            def.LinearDamping = _linearDamping;
            def.AngularDamping = _angularDamping;
            def.GravityScale = _useGravity ? 1f : 0f;
            def.Ccd = _collisionDetectionMode != CollisionDetectionMode.Discrete;
            def.Locks = AxisLocksOf(_constraints);
            def.Name = name;
            _body = World.CreateBody(def);
            SeenTransformVersion = transform.HierarchyVersion;
            scene.OnRigidbodyActivated(this);
            ApplyMass();
        }

        internal override void Deactivate()
        {
            if (!HasBody) return;
            BodyRef r = World.GetBody(_body);
            _linearVelocity = r.LinearVelocity;
            _angularVelocity = r.AngularVelocity;
            BodyHandle old = _body;
            _body = default;
            scene.OnRigidbodyDeactivated(this, old);
        }

        /// <summary>
        /// Unity's constraint flags as the core's axis locks: the same six axes in the same
        /// order, one bit higher (Unity's bit 0 is unused), so the map is a shift.
        /// </summary>
        internal static AxisLocks AxisLocksOf(RigidbodyConstraints c) => (AxisLocks)((int)c >> 1);

        /// <summary>
        /// Recomputes mass properties from the attached colliders: their distribution scaled to
        /// <see cref="mass"/>, the centre moved to <see cref="centerOfMass"/> when set (frozen
        /// rotation axes are the core's business: it projects the inertia).
        /// </summary>
        internal void ApplyMass()
        {
            if (!HasBody || _isKinematic) return;
            MassProperties m = World.ComputeShapeMass(_body);
            m = m.Mass > 0 ? m.WithMass(_mass) : new MassProperties(_mass, Vector3.Zero, Mat3.Identity * _mass);
            if (_centerOfMass.HasValue) m.Center = _centerOfMass.Value;
            World.SetMassProperties(_body, m);
        }

        // A body with a non-convex mesh must be kinematic (Unity: "non-convex MeshCollider with
        // non-kinematic Rigidbody is no longer supported").
        internal void ValidateColliders()
        {
            for (int k = 0; k < Colliders.Count; k++) Colliders[k].CheckBody(this);
        }

        internal void WriteTransform(in Pose pose)
        {
            transform.SetWorldPoseSilently(pose);
            SeenTransformVersion = transform.HierarchyVersion;
        }
    }
}
