using System.Numerics;

namespace Fulcrum
{
    /// <summary>
    /// Everything needed to create a body. Start from <see cref="Default"/> (or
    /// <see cref="Dynamic"/>/<see cref="Static"/>) and set the fields you need.
    /// Mass comes from the shapes' densities unless <see cref="Mass"/> is set.
    /// </summary>
    public struct BodyDef
    {
        /// <summary>Static, kinematic or dynamic. Default: Dynamic.</summary>
        public BodyType Type;
        /// <summary>World position of the body origin, metres. Default: 0.</summary>
        public Vector3 Position;
        /// <summary>World rotation (normalised on creation). Default: identity.</summary>
        public Quaternion Rotation;
        /// <summary>Velocity of the centre of mass, m/s. Default: 0.</summary>
        public Vector3 LinearVelocity;
        /// <summary>World angular velocity, rad/s. Default: 0.</summary>
        public Vector3 AngularVelocity;
        /// <summary>Linear damping rate, 1/s (v decays as 1/(1 + c dt) per step). Default: 0.</summary>
        public float LinearDamping;
        /// <summary>Angular damping rate, 1/s. Default: 0.</summary>
        public float AngularDamping;
        /// <summary>Multiplier on world gravity. Default: 1.</summary>
        public float GravityScale;
        /// <summary>
        /// Mass in kg. 0 (the default) means "from the shapes' densities"; a positive value
        /// scales the shapes' mass distribution (centre and inertia shape kept) to this mass.
        /// </summary>
        public float Mass;
        /// <summary>Whether the body may fall asleep when it rests. Default: true.</summary>
        public bool AllowSleep;
        /// <summary>Whether the body starts awake. Default: true.</summary>
        public bool IsAwake;
        /// <summary>Continuous collision: sweep this body against the world so it cannot tunnel. Default: false.</summary>
        public bool Ccd;
        /// <summary>
        /// World axes the body may not translate along or rotate about (see <see cref="AxisLocks"/>):
        /// enforced inside the solver, so contacts and joints see the reduced mobility. Dynamic
        /// bodies only. Default: None.
        /// </summary>
        public AxisLocks Locks;
        /// <summary>A name for traces, errors and debugging. Default: null.</summary>
        public string? Name;
        /// <summary>Free for the user: a number carried back in events and queries. Default: 0.</summary>
        public ulong UserData;

        /// <summary>A dynamic body at the origin with the defaults documented on each field.</summary>
        public static BodyDef Default => new BodyDef
        {
            Type = BodyType.Dynamic,
            Rotation = Quaternion.Identity,
            GravityScale = 1f,
            AllowSleep = true,
            IsAwake = true,
        };

        /// <summary>A dynamic body at <paramref name="position"/>.</summary>
        public static BodyDef Dynamic(Vector3 position)
        {
            BodyDef d = Default;
            d.Position = position;
            return d;
        }

        /// <summary>A static body at <paramref name="position"/>.</summary>
        public static BodyDef Static(Vector3 position)
        {
            BodyDef d = Default;
            d.Type = BodyType.Static;
            d.Position = position;
            return d;
        }

        /// <summary>A kinematic body at <paramref name="position"/>.</summary>
        public static BodyDef Kinematic(Vector3 position)
        {
            BodyDef d = Default;
            d.Type = BodyType.Kinematic;
            d.Position = position;
            return d;
        }
    }
}
