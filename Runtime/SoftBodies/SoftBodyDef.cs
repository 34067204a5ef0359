using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Everything needed to create a soft body; the fields map one to one onto the scene file's
    /// <c>softBodies</c> entry (mesh, material, position, pinned, initialDeformation, probes).
    /// Start from <see cref="Default"/>; each field documents its default and unit. Checked by
    /// <see cref="SoftBodyWorldExtensions.CreateSoftBody"/> before anything changes.
    /// </summary>
    public struct SoftBodyDef
    {
        /// <summary>Name for traces and errors. Default: null.</summary>
        public string? Name;
        /// <summary>The rest shape (tets or a triangle shell). Required.</summary>
        public SoftMesh? Mesh;
        /// <summary>The material. Default: <see cref="NeoHookeanMaterial.Default"/>.</summary>
        public NeoHookeanMaterial Material;
        /// <summary>Where the mesh origin goes in the world, metres. Default: origin.</summary>
        public Vector3 Position;
        /// <summary>Rotation of the mesh about its origin. Default: identity.</summary>
        public Quaternion Rotation;
        /// <summary>Initial velocity of every vertex, m/s. Default: zero.</summary>
        public Vector3 LinearVelocity;
        /// <summary>
        /// Maps rest positions to starting positions about the mesh centre (<see cref="SoftMesh.Center"/>):
        /// x = Position + Rotation (c + D (X - c)). A negative determinant starts the body inverted.
        /// Must be invertible. Default: identity.
        /// </summary>
        public Mat3 InitialDeformation;
        /// <summary>Rest-space boxes whose vertices are pinned to the world or attached to a body. Default: none.</summary>
        public SoftPin[]? Pins;
        /// <summary>Material points in rest coordinates whose world positions are traced (see <see cref="SoftBody.GetProbe"/>). Default: none.</summary>
        public Vector3[]? Probes;
        /// <summary>
        /// XPBD substeps per world step; 0 picks one per 1/600 s of step (10 at 60 Hz), enough to
        /// keep every E from 1e3 to 1e9 Pa finite and bounded. Default: 0 (automatic).
        /// </summary>
        public int Substeps;
        /// <summary>Constraint iterations per substep (multipliers are kept across them). &gt;= 1. Default: 1.</summary>
        public int Iterations;
        /// <summary>
        /// Stiffness-proportional (Rayleigh) damping time, seconds: each elastic constraint is
        /// damped as if by a dashpot of stiffness times this time, so a mode of angular
        /// frequency w gets damping ratio w * time / 2 whatever the step. Applied as an implicit
        /// velocity pass after each substep: it only ever removes kinetic energy and leaves linear
        /// and angular momentum and rigid rotation untouched. 0.01 s gives a 0.4 m rubber block
        /// (fundamental ~38 Hz) a restitution of 0.33; 0.001 s (damping ratio ~0.1 there, a
        /// rubber-like loss) gives 0.48, but soft jellies then ring for longer than 3 s. &gt;= 0. Default: 0.01 s.
        /// </summary>
        public float DampingTime;
        /// <summary>Velocity damping, 1/s (v /= 1 + c h per substep, the stable form of exp(-c t)). &gt;= 0. Default: 0.</summary>
        public float LinearDamping;
        /// <summary>Multiplies world gravity. Default: 1.</summary>
        public float GravityScale;
        /// <summary>Coulomb friction against rigid shapes (combined with the shape's by its mode). &gt;= 0. Default: 0.5.</summary>
        public float Friction;
        /// <summary>Vertices keep this distance from rigid shapes (and, with self-collision, from each other: twice it), metres. &gt;= 0. Default: 0.005 m.</summary>
        public float CollisionRadius;
        /// <summary>Collide with rigid shapes. Default: true.</summary>
        public bool CollideWithShapes;
        /// <summary>
        /// Collide with other soft bodies: surface vertices against the other body's surface
        /// triangles, both ways, with friction (the mean of the two <see cref="Friction"/>s), momentum
        /// conserving. On by default, as rigid bodies collide by default; two soft bodies meet
        /// only when both have it on and each one's <see cref="CollidesWith"/> holds the other's
        /// <see cref="Layer"/>, so put bodies that should overlap (a sleeve on an arm) on layers
        /// that exclude each other. Costs nothing while the bodies' bounds are apart. Default: true.
        /// </summary>
        public bool CollideWithSoftBodies;
        /// <summary>The collision layer (0..31) rigid shapes' and other soft bodies' CollidesWith masks test. Default: 0.</summary>
        public int Layer;
        /// <summary>Bit mask of the layers (of shapes and of other soft bodies) this body collides with. Default: all.</summary>
        public uint CollidesWith;
        /// <summary>Vertex-vertex self-collision through a spatial hash. Default: false.</summary>
        public bool SelfCollision;
        /// <summary>Plastic flow of tets. Default: <see cref="SoftPlasticity.None"/>.</summary>
        public SoftPlasticity Plasticity;
        /// <summary>Shells only: sheet thickness, metres (mass per area = density * thickness; bending rigidity E t^3 / 12(1 - nu^2)). &gt; 0. Default: 0.0005 m.</summary>
        public float Thickness;
        /// <summary>Shells only: multiplies the physical bending rigidity; 0 turns bending off. &gt;= 0. Default: 1.</summary>
        public float BendingScale;

        /// <summary>
        /// The elastic solver (see <see cref="SoftSolver"/>). Default <see cref="SoftSolver.Xpbd"/>;
        /// <see cref="SoftSolver.Newton"/> converges on stiff materials and needs a tetrahedral mesh.
        /// </summary>
        public SoftSolver Solver;

        /// <summary>The defaults documented on each field (no mesh yet).</summary>
        public static SoftBodyDef Default => new SoftBodyDef
        {
            Material = NeoHookeanMaterial.Default,
            Rotation = Quaternion.Identity,
            InitialDeformation = Mat3.Identity,
            Substeps = 0,
            Iterations = 1,
            DampingTime = 0.01f,
            LinearDamping = 0f,
            GravityScale = 1f,
            Friction = 0.5f,
            CollisionRadius = 0.005f,
            CollideWithShapes = true,
            CollideWithSoftBodies = true,
            Layer = 0,
            CollidesWith = uint.MaxValue,
            Plasticity = SoftPlasticity.None,
            Thickness = 0.0005f,
            BendingScale = 1f,
        };

        /// <summary>A default body of <paramref name="mesh"/> and <paramref name="material"/> at <paramref name="position"/>.</summary>
        public static SoftBodyDef Of(SoftMesh mesh, in NeoHookeanMaterial material, Vector3 position)
        {
            SoftBodyDef def = Default;
            def.Mesh = mesh;
            def.Material = material;
            def.Position = position;
            return def;
        }

        /// <summary>Checks every field that needs no world; throws an <see cref="ArgumentException"/> naming the first bad one.</summary>
        public readonly void Validate()
        {
            if (Mesh == null) throw new ArgumentException("softBody.Mesh is required.", "softBody.Mesh");
            Material.Validate();
            Limits.CheckPosition(Position, "softBody.Position");
            Mathematics.Validate.Rotation(Rotation, "softBody.Rotation");
            Limits.CheckSpeed(LinearVelocity, "softBody.LinearVelocity");
            if (!InitialDeformation.IsFinite) throw new ArgumentException($"softBody.InitialDeformation must be finite, got {InitialDeformation}.", "softBody.InitialDeformation");
            if (!(MathF.Abs(InitialDeformation.Determinant) > 1e-6f))
                throw new ArgumentException($"softBody.InitialDeformation must be invertible, got det = {InitialDeformation.Determinant}.", "softBody.InitialDeformation");
            if (Substeps < 0 || Substeps > 1000) throw new ArgumentException($"softBody.Substeps must be in [0, 1000], got {Substeps}.", "softBody.Substeps");
            if (Iterations < 1 || Iterations > 1000) throw new ArgumentException($"softBody.Iterations must be in [1, 1000], got {Iterations}.", "softBody.Iterations");
            if (Solver != SoftSolver.Xpbd && Solver != SoftSolver.Newton) throw new ArgumentException($"softBody.Solver must be Xpbd or Newton, got {(int)Solver}.", "softBody.Solver");
            if (Solver == SoftSolver.Newton && Mesh.IsShell) throw new ArgumentException("softBody.Solver Newton solves tetrahedra; a shell mesh needs Xpbd.", "softBody.Solver");
            Mathematics.Validate.NonNegative(DampingTime, "softBody.DampingTime");
            Mathematics.Validate.NonNegative(LinearDamping, "softBody.LinearDamping");
            Mathematics.Validate.Finite(GravityScale, "softBody.GravityScale");
            Mathematics.Validate.NonNegative(Friction, "softBody.Friction");
            Mathematics.Validate.NonNegative(CollisionRadius, "softBody.CollisionRadius");
            if (Layer < 0 || Layer > 31) throw new ArgumentException($"softBody.Layer must be in 0..31, got {Layer}.", "softBody.Layer");
            Plasticity.Validate();
            if (Mesh.IsShell)
            {
                Mathematics.Validate.Positive(Thickness, "softBody.Thickness");
                Mathematics.Validate.NonNegative(BendingScale, "softBody.BendingScale");
            }
            if (Probes != null)
                for (int i = 0; i < Probes.Length; i++)
                    Mathematics.Validate.Finite(Probes[i], $"softBody.Probes[{i}]");
            if (Pins != null)
            {
                for (int i = 0; i < Pins.Length; i++)
                {
                    Mathematics.Validate.Finite(Pins[i].Min, $"softBody.Pins[{i}].Min");
                    Mathematics.Validate.Finite(Pins[i].Max, $"softBody.Pins[{i}].Max");
                    Vector3 min = Pins[i].Min, max = Pins[i].Max;
                    if (!(min.X <= max.X && min.Y <= max.Y && min.Z <= max.Z))
                        throw new ArgumentException($"softBody.Pins[{i}].Min must be <= Max on every axis, got {min} .. {max}.", $"softBody.Pins[{i}]");
                    if (CountInside(Mesh, min, max) == 0)
                        throw new ArgumentException($"softBody.Pins[{i}] selects no vertex: no rest vertex lies in {min} .. {max}.", $"softBody.Pins[{i}]");
                }
            }
        }

        /// <summary>Rest vertices inside a pin box; the box is widened by a relative 1e-5 so faces given exactly are caught despite rounding.</summary>
        internal static int CountInside(SoftMesh mesh, Vector3 min, Vector3 max)
        {
            int n = 0;
            ReadOnlySpan<Vector3> v = mesh.Vertices;
            for (int i = 0; i < v.Length; i++) if (PinContains(mesh, min, max, v[i])) n++;
            return n;
        }

        internal static bool PinContains(SoftMesh mesh, Vector3 min, Vector3 max, Vector3 p)
        {
            float tol = 1e-5f * MathF.Max(mesh.Bounds.Size.Length(), 1e-6f);
            return p.X >= min.X - tol && p.Y >= min.Y - tol && p.Z >= min.Z - tol
                && p.X <= max.X + tol && p.Y <= max.Y + tol && p.Z <= max.Z + tol;
        }
    }
}
