using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Scenes
{
    /// <summary>
    /// An entry of <c>softBodies</c>: a Neo-Hookean solid meshed from <see cref="Mesh"/>. Kept
    /// as data by Core; Fulcrum.SoftBodies turns it into a soft body.
    /// </summary>
    public sealed class SceneSoftBody
    {
        /// <summary><c>name</c>: unique among soft bodies. Required.</summary>
        public string Name { get; set; } = "";

        /// <summary><c>mesh</c>: the rest shape. Required.</summary>
        public SceneSoftMesh? Mesh { get; set; }

        /// <summary><c>material</c>: the constitutive model and its constants. Required.</summary>
        public SceneSoftMaterial? Material { get; set; }

        /// <summary><c>position</c>: world position of the mesh centre, m. Default: 0.</summary>
        public Vector3 Position { get; set; }

        /// <summary><c>rotation</c>: a quaternion <c>[x, y, z, w]</c> turning the mesh about its centre (normalised when built). Default: identity.</summary>
        public Quaternion Rotation { get; set; } = Quaternion.Identity;

        /// <summary><c>velocity</c>: initial velocity of every vertex, m/s. Default: 0.</summary>
        public Vector3 Velocity { get; set; }

        /// <summary><c>pinned</c>: rest-space boxes whose vertices are fixed or attached to a body. Default: none.</summary>
        public List<ScenePin> Pinned { get; } = new List<ScenePin>();

        /// <summary>
        /// <c>initialDeformation</c>: maps rest positions (about the mesh centre) to starting
        /// positions; written as three rows <c>[[a,b,c],[d,e,f],[g,h,i]]</c>. Non-singular; a
        /// negative determinant starts the body inverted. Default: identity.
        /// </summary>
        public Mat3 InitialDeformation { get; set; } = Mat3.Identity;

        /// <summary><c>probes</c>: material points in rest coordinates (about the mesh centre) reported in traces, m. Default: none.</summary>
        public List<Vector3> Probes { get; } = new List<Vector3>();

        /// <summary><c>substeps</c>: XPBD substeps per world step, 0..1000; 0 picks one per 1/600 s of step. Null: the engine's default (automatic).</summary>
        public int? Substeps { get; set; }

        /// <summary><c>iterations</c>: XPBD constraint iterations per substep, 1..1000. Null: the engine's default (1).</summary>
        public int? Iterations { get; set; }

        /// <summary>
        /// <c>dampingTime</c>: stiffness-proportional (Rayleigh) damping time, s, &gt;= 0; a mode of
        /// angular frequency w gets damping ratio w * dampingTime / 2. Null: the engine's default.
        /// </summary>
        public float? DampingTime { get; set; }

        /// <summary>
        /// <c>solver</c>: the elastic solver, <c>"xpbd"</c> (default) or <c>"newton"</c> (implicit
        /// Euler with direct Newton steps, for small stiff bodies; tetrahedral meshes only). Null:
        /// the engine's default.
        /// </summary>
        public string? Solver { get; set; }

        /// <summary><c>linearDamping</c>: velocity damping, 1/s, &gt;= 0. Null: the engine's default (0).</summary>
        public float? LinearDamping { get; set; }

        /// <summary><c>gravityScale</c>: multiplies the scene's gravity, finite. Null: 1.</summary>
        public float? GravityScale { get; set; }

        /// <summary><c>friction</c>: Coulomb friction against rigid shapes and other soft bodies, &gt;= 0. Null: the engine's default (0.5).</summary>
        public float? Friction { get; set; }

        /// <summary><c>collisionRadius</c>: the distance vertices keep from what they touch, m, &gt;= 0. Null: the engine's default (0.005 m).</summary>
        public float? CollisionRadius { get; set; }

        /// <summary><c>collideWithShapes</c>: collide with rigid bodies' shapes. Null: true.</summary>
        public bool? CollideWithShapes { get; set; }

        /// <summary><c>collideWithSoftBodies</c>: collide with other soft bodies (both must have it on). Null: true.</summary>
        public bool? CollideWithSoftBodies { get; set; }

        /// <summary><c>selfCollision</c>: vertex-vertex collision within this body. Null: false.</summary>
        public bool? SelfCollision { get; set; }

        /// <summary><c>layer</c>: the collision layer, 0..31. Null: 0.</summary>
        public int? Layer { get; set; }

        /// <summary>
        /// <c>collidesWith</c>: the layers (each 0..31) this body collides with, as a list such as
        /// <c>[0, 2]</c>; empty: none. Null: every layer.
        /// </summary>
        public int[]? CollidesWith { get; set; }

        /// <summary><c>plasticity</c> (an extension of fulcrum-scene/1). Default: null, elastic.</summary>
        public ScenePlasticity? Plasticity { get; set; }
    }
}
