using System.Numerics;

namespace Fulcrum.Scenes
{
    /// <summary>One entry of <c>bodies</c> (or one body made by a generator).</summary>
    public sealed class SceneBody
    {
        /// <summary><c>name</c>: unique among all bodies, generated ones included. Required.</summary>
        public string Name { get; set; } = "";

        /// <summary><c>type</c>: <c>"static"</c>, <c>"kinematic"</c> or <c>"dynamic"</c>. Default: dynamic.</summary>
        public BodyType Type { get; set; } = BodyType.Dynamic;

        /// <summary><c>shape</c>: the collision shape (a compound for several). Required.</summary>
        public SceneShape? Shape { get; set; }

        /// <summary>
        /// <c>mass</c>, kg, &gt; 0, dynamic bodies only; null: from the density. A mass overrides
        /// the density of the body's material: the shape's mass distribution is scaled to it.
        /// </summary>
        public float? Mass { get; set; }

        /// <summary>
        /// <c>density</c>, kg/m^3, &gt; 0 (an extension of fulcrum-scene/1): this body's own
        /// density, overriding its material's. Giving both <c>mass</c> and <c>density</c> on one
        /// body is an error. Null: the material's density (1000 without a material).
        /// </summary>
        public float? Density { get; set; }

        /// <summary><c>material</c>: the name of an entry of <c>materials</c>; null: friction 0.6, restitution 0, density 1000.</summary>
        public string? Material { get; set; }

        /// <summary><c>position</c>: world position of the body origin, m. Default: 0.</summary>
        public Vector3 Position { get; set; }

        /// <summary><c>rotation</c>: a quaternion <c>[x, y, z, w]</c> (normalised when built). Default: identity.</summary>
        public Quaternion Rotation { get; set; } = Quaternion.Identity;

        /// <summary><c>velocity</c>: linear velocity of the centre of mass, m/s. Default: 0.</summary>
        public Vector3 Velocity { get; set; }

        /// <summary><c>angularVelocity</c>: world angular velocity, rad/s. Default: 0.</summary>
        public Vector3 AngularVelocity { get; set; }

        /// <summary><c>ccd</c>: continuous collision for this body. Default: false.</summary>
        public bool Ccd { get; set; }

        /// <summary>
        /// <c>lockAxes</c> (an extension of fulcrum-scene/1): the world axes a dynamic body may not
        /// move along or turn about, as an array of names from <c>"linearX"</c>, <c>"linearY"</c>,
        /// <c>"linearZ"</c>, <c>"angularX"</c>, <c>"angularY"</c>, <c>"angularZ"</c> (see
        /// <see cref="AxisLocks"/>). Default: none (the field is left out).
        /// </summary>
        public AxisLocks LockAxes { get; set; }
    }
}
