using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// Mass, centre of mass and inertia tensor of a body or shape. The inertia is taken about
    /// the centre of mass and expressed in the local frame of the body (or shape).
    /// </summary>
    public struct MassProperties
    {
        /// <summary>Mass in kilograms.</summary>
        public float Mass;
        /// <summary>Centre of mass in the local frame, metres.</summary>
        public Vector3 Center;
        /// <summary>Inertia tensor about <see cref="Center"/> in the local frame, kg m^2.</summary>
        public Mat3 Inertia;

        /// <summary>Builds mass properties from their parts.</summary>
        public MassProperties(float mass, Vector3 center, Mat3 inertia)
        {
            Mass = mass;
            Center = center;
            Inertia = inertia;
        }

        /// <summary>A solid sphere: m = rho 4/3 pi r^3, I = 2/5 m r^2.</summary>
        public static MassProperties Sphere(float radius, float density)
        {
            float m = density * (4f / 3f) * MathF.PI * radius * radius * radius;
            float i = 0.4f * m * radius * radius;
            return new MassProperties(m, Vector3.Zero, Mat3.Diagonal(new Vector3(i)));
        }

        /// <summary>A solid box of half-extents h: m = 8 rho hx hy hz, Ixx = m/3 (hy^2 + hz^2).</summary>
        public static MassProperties Box(Vector3 halfExtents, float density)
        {
            Vector3 h = halfExtents;
            float m = density * 8f * h.X * h.Y * h.Z;
            Vector3 s = h * h;
            return new MassProperties(m, Vector3.Zero,
                Mat3.Diagonal(m / 3f * new Vector3(s.Y + s.Z, s.X + s.Z, s.X + s.Y)));
        }

        /// <summary>
        /// A solid capsule along the local y axis: a cylinder of radius r and length 2h plus two
        /// hemispheres. Each hemisphere (total mass ms) contributes 2/5 ms r^2 about y and, by
        /// the parallel-axis theorem from its centroid 3r/8 beyond the cylinder's end,
        /// ms (2/5 r^2 + h^2 + 3/4 h r) about x and z.
        /// </summary>
        public static MassProperties Capsule(float radius, float halfHeight, float density)
        {
            float r = radius, h = halfHeight, r2 = r * r;
            float mc = density * MathF.PI * r2 * 2f * h;
            float ms = density * (4f / 3f) * MathF.PI * r2 * r;
            float iy = mc * r2 * 0.5f + ms * 0.4f * r2;
            float ix = mc * (r2 / 4f + h * h / 3f) + ms * (0.4f * r2 + h * h + 0.75f * h * r);
            return new MassProperties(mc + ms, Vector3.Zero, Mat3.Diagonal(new Vector3(ix, iy, ix)));
        }

        /// <summary>
        /// The same mass distribution seen from a frame in which its own frame sits at
        /// <paramref name="pose"/>: the centre moves and the tensor rotates (R I R^T).
        /// </summary>
        public readonly MassProperties Transformed(in Pose pose)
        {
            Mat3 r = Mat3.FromQuaternion(pose.Rotation);
            return new MassProperties(Mass, pose.TransformPoint(Center), r * Inertia * r.Transposed);
        }

        /// <summary>The same shape with every mass scaled so that the total is <paramref name="mass"/>.</summary>
        public readonly MassProperties WithMass(float mass)
        {
            float s = Mass > 0 ? mass / Mass : 0;
            return new MassProperties(mass, Center, Inertia * s);
        }

        /// <summary>
        /// The sum of two distributions: masses add, centres average by mass, each tensor moves
        /// to the common centre by the parallel-axis theorem I + m (|d|^2 E - d d^T).
        /// </summary>
        public static MassProperties Combine(in MassProperties a, in MassProperties b)
        {
            float m = a.Mass + b.Mass;
            if (!(m > 0)) return default;
            Vector3 c = (a.Center * a.Mass + b.Center * b.Mass) / m;
            return new MassProperties(m, c, Shift(a, c) + Shift(b, c));
        }

        static Mat3 Shift(in MassProperties p, Vector3 to)
        {
            Vector3 d = p.Center - to;
            return p.Inertia + (Mat3.Diagonal(new Vector3(d.LengthSquared())) - Mat3.Outer(d, d)) * p.Mass;
        }

        /// <summary>Checks that mass is finite and &gt; 0, the centre finite and the tensor finite and symmetric positive semi-definite in its diagonal.</summary>
        public readonly void Validate(string name)
        {
            Mathematics.Validate.Positive(Mass, name + ".Mass");
            Mathematics.Validate.Finite(Center, name + ".Center");
            if (!Inertia.IsFinite) throw new ArgumentException($"{name}.Inertia must be finite.", name + ".Inertia");
            Vector3 d = Inertia.DiagonalVector;
            if (d.X < 0 || d.Y < 0 || d.Z < 0)
                throw new ArgumentException($"{name}.Inertia must have a non-negative diagonal, got {d}.", name + ".Inertia");
        }
    }
}
