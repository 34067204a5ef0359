using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// A short-lived view of one body for reading and writing, from
    /// <see cref="World.GetBody"/>. Setters check their value (finite, in range) and throw
    /// before changing anything. Every access re-checks the handle, so a view of a body
    /// destroyed meanwhile throws <see cref="StaleHandleException"/>.
    /// </summary>
    public readonly ref struct BodyRef
    {
        readonly World _world;
        readonly int _slot;
        readonly int _generation;

        internal BodyRef(World world, int slot, int generation)
        {
            _world = world;
            _slot = slot;
            _generation = generation;
        }

        BodyStorage B
        {
            get
            {
                BodyStorage b = _world.Bodies;
                if (b.Generation[_slot] != _generation || b.ActiveIndex[_slot] < 0)
                    throw new StaleHandleException($"BodyHandle({_slot}:{_generation}) was destroyed while a BodyRef to it was in use.");
                return b;
            }
        }

        BodyStorage Writable
        {
            get
            {
                if (_world.IsStepping) throw new InvalidOperationException("A body cannot be changed during Step (from a callback).");
                return B;
            }
        }

        /// <summary>The handle of this body.</summary>
        public BodyHandle Handle => new BodyHandle(_slot, _generation, _world.Id);

        /// <summary>Static, kinematic or dynamic.</summary>
        public BodyType Type => B.Type[_slot];

        /// <summary>The body's name (for traces and errors), or null.</summary>
        public string? Name => B.Name[_slot];

        /// <summary>The user's number from <see cref="BodyDef.UserData"/>.</summary>
        public ulong UserData
        {
            get => B.UserData[_slot];
            set => Writable.UserData[_slot] = value;
        }

        /// <summary>World position of the body origin, metres. Setting it teleports the body and wakes it.</summary>
        public Vector3 Position
        {
            get => B.Position[_slot];
            set
            {
                Limits.CheckPosition(value, nameof(Position));
                BodyStorage b = Writable;
                b.Position[_slot] = value;
                b.PreviousPosition[_slot] = value;
                b.SyncCenterFromOrigin(_slot);
                _world.Wake(_slot);
            }
        }

        /// <summary>World rotation. Setting it (normalised) teleports the body and wakes it.</summary>
        public Quaternion Rotation
        {
            get => B.Rotation[_slot];
            set
            {
                Quaternion q = Validate.Rotation(value, nameof(Rotation));
                BodyStorage b = Writable;
                b.Rotation[_slot] = q;
                b.PreviousRotation[_slot] = q;
                b.SyncCenterFromOrigin(_slot);
                b.UpdateWorldInertia(_slot);
                _world.Wake(_slot);
            }
        }

        /// <summary>The body's pose (origin and rotation).</summary>
        public Pose Pose => new Pose(Position, Rotation);

        /// <summary>World centre of mass, metres.</summary>
        public Vector3 CenterOfMass => B.Center[_slot];

        /// <summary>Centre of mass in the body frame, metres.</summary>
        public Vector3 LocalCenterOfMass => B.LocalCenter[_slot];

        /// <summary>Velocity of the centre of mass, m/s. Setting it wakes the body; ignored for static bodies.</summary>
        public Vector3 LinearVelocity
        {
            get => B.LinearVelocity[_slot];
            set
            {
                Limits.CheckSpeed(value, nameof(LinearVelocity));
                BodyStorage b = Writable;
                if (b.Type[_slot] == BodyType.Static) return;
                b.LinearVelocity[_slot] = value;
                _world.Wake(_slot);
            }
        }

        /// <summary>World angular velocity, rad/s. Setting it wakes the body; ignored for static bodies.</summary>
        public Vector3 AngularVelocity
        {
            get => B.AngularVelocity[_slot];
            set
            {
                Limits.CheckSpeed(value, nameof(AngularVelocity));
                BodyStorage b = Writable;
                if (b.Type[_slot] == BodyType.Static) return;
                b.AngularVelocity[_slot] = value;
                _world.Wake(_slot);
            }
        }

        /// <summary>Mass, kg (0 for static and kinematic bodies).</summary>
        public float Mass => B.Mass[_slot];

        /// <summary>1 / mass (0 for static and kinematic bodies).</summary>
        public float InverseMass => B.InverseMass[_slot];

        /// <summary>Inertia tensor about the centre of mass in the body frame, kg m^2.</summary>
        public Mat3 InertiaLocal => B.InertiaLocal[_slot];

        /// <summary>Inverse inertia tensor in world axes (refreshed with the pose).</summary>
        public Mat3 InverseInertiaWorld => B.InverseInertiaWorld[_slot];

        /// <summary>World angular momentum about the centre of mass, R I R^T w, kg m^2/s.</summary>
        public Vector3 AngularMomentum
        {
            get
            {
                BodyStorage b = B;
                Mat3 r = Mat3.FromQuaternion(b.Rotation[_slot]);
                return r * (b.InertiaLocal[_slot] * r.TransposeMultiply(b.AngularVelocity[_slot]));
            }
        }

        /// <summary>Kinetic energy 1/2 m v^2 + 1/2 w . L, joules (0 for non-dynamic bodies).</summary>
        public float KineticEnergy
        {
            get
            {
                BodyStorage b = B;
                if (b.Type[_slot] != BodyType.Dynamic) return 0;
                return 0.5f * b.Mass[_slot] * b.LinearVelocity[_slot].LengthSquared()
                     + 0.5f * Vector3.Dot(b.AngularVelocity[_slot], AngularMomentum);
            }
        }

        /// <summary>Linear damping rate, 1/s (&gt;= 0).</summary>
        public float LinearDamping
        {
            get => B.LinearDamping[_slot];
            set
            {
                Validate.NonNegative(value, nameof(LinearDamping));
                Writable.LinearDamping[_slot] = value;
            }
        }

        /// <summary>Angular damping rate, 1/s (&gt;= 0).</summary>
        public float AngularDamping
        {
            get => B.AngularDamping[_slot];
            set
            {
                Validate.NonNegative(value, nameof(AngularDamping));
                Writable.AngularDamping[_slot] = value;
            }
        }

        /// <summary>Multiplier on world gravity.</summary>
        public float GravityScale
        {
            get => B.GravityScale[_slot];
            set
            {
                Limits.CheckGravityScale(value, nameof(GravityScale));
                Writable.GravityScale[_slot] = value;
            }
        }

        /// <summary>
        /// World axes the body may not translate along or rotate about (see <see cref="AxisLocks"/>
        /// and <see cref="World.SetAxisLocks"/>). Unknown bits throw before anything changes.
        /// </summary>
        public AxisLocks Locks
        {
            get => B.Locks[_slot];
            set
            {
                _ = Writable;
                _world.SetAxisLocks(Handle, value);
            }
        }

        /// <summary>Whether continuous collision sweeps this body.</summary>
        public bool Ccd
        {
            get => B.Ccd[_slot];
            set
            {
                _ = Writable;
                _world.SetCcd(_slot, value);
            }
        }

        /// <summary>Whether the body may fall asleep.</summary>
        public bool AllowSleep
        {
            get => B.AllowSleep[_slot];
            set
            {
                BodyStorage b = Writable;
                b.AllowSleep[_slot] = value;
                if (!value) _world.Wake(_slot);
            }
        }

        /// <summary>Whether the body is awake (static bodies never are).</summary>
        public bool IsAwake => B.Awake[_slot];

        /// <summary>Force accumulated for the next step, N.</summary>
        public Vector3 Force => B.Force[_slot];

        /// <summary>Torque accumulated for the next step, N m.</summary>
        public Vector3 Torque => B.Torque[_slot];

        /// <summary>Velocity of the body's material point at a world position, m/s: v + w x (p - c).</summary>
        public Vector3 GetPointVelocity(Vector3 worldPoint)
        {
            BodyStorage b = B;
            return b.LinearVelocity[_slot] + Vector3.Cross(b.AngularVelocity[_slot], worldPoint - b.Center[_slot]);
        }

        /// <summary>See <see cref="World.AddForce"/>.</summary>
        public void AddForce(Vector3 force, ForceMode mode = ForceMode.Force) => _world.AddForce(Handle, force, mode);

        /// <summary>See <see cref="World.AddForceAtPosition"/>.</summary>
        public void AddForceAtPosition(Vector3 force, Vector3 worldPoint, ForceMode mode = ForceMode.Force) =>
            _world.AddForceAtPosition(Handle, force, worldPoint, mode);

        /// <summary>See <see cref="World.AddTorque"/>.</summary>
        public void AddTorque(Vector3 torque, ForceMode mode = ForceMode.Force) => _world.AddTorque(Handle, torque, mode);

        /// <summary>See <see cref="World.SetKinematicTarget"/>.</summary>
        public void SetKinematicTarget(Vector3 position, Quaternion rotation) => _world.SetKinematicTarget(Handle, position, rotation);

        /// <summary>Wakes the body.</summary>
        public void WakeUp()
        {
            _ = Writable;
            _world.Wake(_slot);
        }
    }
}
