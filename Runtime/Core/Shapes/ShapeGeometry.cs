using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// The geometry of one shape in its own frame: an immutable description built by the
    /// static factories, which reject zero, negative and non-finite sizes with the field name.
    /// Hulls and meshes keep their (shared, immutable) data in <see cref="Data"/>.
    /// </summary>
    public readonly struct ShapeGeometry
    {
        /// <summary>The kind of geometry.</summary>
        public readonly ShapeType Type;
        /// <summary>Sphere or capsule radius, metres.</summary>
        public readonly float Radius;
        /// <summary>Capsule: half the length of the inner segment along local y, metres.</summary>
        public readonly float HalfHeight;
        /// <summary>Box half-extents, metres.</summary>
        public readonly Vector3 HalfExtents;
        /// <summary>Plane: unit outward normal (the solid side is where n . x &lt;= offset).</summary>
        public readonly Vector3 Normal;
        /// <summary>Plane: signed distance of the surface from the origin along <see cref="Normal"/>, metres.</summary>
        public readonly float Offset;
        /// <summary>Convex hull or triangle mesh data; null for the analytic kinds.</summary>
        public readonly object? Data;

        ShapeGeometry(ShapeType type, float radius, float halfHeight, Vector3 halfExtents, Vector3 normal, float offset, object? data)
        {
            Type = type;
            Radius = radius;
            HalfHeight = halfHeight;
            HalfExtents = halfExtents;
            Normal = normal;
            Offset = offset;
            Data = data;
        }

        /// <summary>A sphere of the given radius (metres, &gt; 0).</summary>
        public static ShapeGeometry Sphere(float radius)
        {
            Validate.Positive(radius, "sphere.radius");
            return new ShapeGeometry(ShapeType.Sphere, radius, 0, Vector3.Zero, Vector3.Zero, 0, null);
        }

        /// <summary>A box of the given half-extents (metres, each &gt; 0).</summary>
        public static ShapeGeometry Box(Vector3 halfExtents)
        {
            Validate.Positive(halfExtents, "box.halfExtents");
            return new ShapeGeometry(ShapeType.Box, 0, 0, halfExtents, Vector3.Zero, 0, null);
        }

        /// <summary>A capsule along local y: radius (&gt; 0) and half-height of the inner segment (&gt;= 0).</summary>
        public static ShapeGeometry Capsule(float radius, float halfHeight)
        {
            Validate.Positive(radius, "capsule.radius");
            Validate.NonNegative(halfHeight, "capsule.halfHeight");
            return new ShapeGeometry(ShapeType.Capsule, radius, halfHeight, Vector3.Zero, Vector3.Zero, 0, null);
        }

        /// <summary>The half-space n . x &lt;= offset (n is normalised here; static bodies only).</summary>
        public static ShapeGeometry Plane(Vector3 normal, float offset)
        {
            Validate.Finite(normal, "plane.normal");
            Validate.Finite(offset, "plane.offset");
            float len = normal.Length();
            if (!(len > 1e-6f)) throw new ArgumentException($"plane.normal must be non-zero, got {normal}.", "plane.normal");
            return new ShapeGeometry(ShapeType.Plane, 0, 0, Vector3.Zero, normal / len, offset, null);
        }

        /// <summary>A convex hull (dynamic bodies allowed). The hull is shared, not copied.</summary>
        public static ShapeGeometry ConvexHull(ConvexHull hull)
        {
            if (hull == null) throw new ArgumentNullException(nameof(hull), "hull must not be null.");
            return new ShapeGeometry(ShapeType.ConvexHull, 0, 0, Vector3.Zero, Vector3.Zero, 0, hull);
        }

        /// <summary>The convex hull of a point cloud (see <see cref="Fulcrum.ConvexHull.Create"/> for what is rejected).</summary>
        public static ShapeGeometry ConvexHull(ReadOnlySpan<Vector3> points) => ConvexHull(Fulcrum.ConvexHull.Create(points));

        /// <summary>A static triangle mesh (static bodies only). The mesh is shared, not copied.</summary>
        public static ShapeGeometry TriangleMesh(TriangleMesh mesh)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh), "mesh must not be null.");
            return new ShapeGeometry(ShapeType.TriangleMesh, 0, 0, Vector3.Zero, Vector3.Zero, 0, mesh);
        }

        /// <summary>Writes every field; <paramref name="dataIndex"/> names the hull or mesh in the state's table (-1 for none).</summary>
        internal void WriteState(StateWriter w, int dataIndex)
        {
            w.Write(Type);
            w.Write(Radius);
            w.Write(HalfHeight);
            w.Write(HalfExtents);
            w.Write(Normal);
            w.Write(Offset);
            w.Write(dataIndex);
        }

        /// <summary>Reads what <see cref="WriteState"/> wrote; <paramref name="data"/> is the state's table of hulls and meshes.</summary>
        internal static ShapeGeometry ReadState(StateReader r, object[] data)
        {
            var type = r.Read<ShapeType>("shape type");
            float radius = r.Read<float>("shape radius"), halfHeight = r.Read<float>("shape half-height");
            Vector3 halfExtents = r.Read<Vector3>("shape half-extents"), normal = r.Read<Vector3>("shape normal");
            float offset = r.Read<float>("shape offset");
            int index = r.Read<int>("shape data index");
            if (type > ShapeType.TriangleMesh) throw r.Error($"unknown shape type {(int)type}.");
            object? d = null;
            if (type == ShapeType.ConvexHull || type == ShapeType.TriangleMesh)
            {
                if ((uint)index >= (uint)data.Length) throw r.Error($"a shape names data {index} of {data.Length}.");
                d = data[index];
                if (type == ShapeType.ConvexHull ? !(d is ConvexHull) : !(d is TriangleMesh)) throw r.Error($"a {type} shape names data of another kind.");
            }
            return new ShapeGeometry(type, radius, halfHeight, halfExtents, normal, offset, d);
        }

        /// <summary>Geometry of another kind carrying its own data (hulls and meshes).</summary>
        internal static ShapeGeometry WithData(ShapeType type, object data, float radius = 0) =>
            new ShapeGeometry(type, radius, 0, Vector3.Zero, Vector3.Zero, 0, data);

        /// <summary>True for kinds that only static bodies may carry (planes and meshes have no volume).</summary>
        public bool IsStaticOnly => Type == ShapeType.Plane || Type == ShapeType.TriangleMesh;

        /// <summary>Mass properties at the given density (kg/m^3) in the shape's own frame.</summary>
        public MassProperties ComputeMass(float density)
        {
            switch (Type)
            {
                case ShapeType.Sphere: return MassProperties.Sphere(Radius, density);
                case ShapeType.Box: return MassProperties.Box(HalfExtents, density);
                case ShapeType.Capsule: return MassProperties.Capsule(Radius, HalfHeight, density);
                case ShapeType.ConvexHull when Data is IMassSource hull: return hull.ComputeMass(density);
                default: return default; // planes and meshes: static only, no mass
            }
        }

        /// <summary>The world-space bounds of the shape at the given world pose.</summary>
        public Aabb ComputeAabb(in Pose pose)
        {
            switch (Type)
            {
                case ShapeType.Sphere:
                    return Aabb.FromCenterExtents(pose.Position, new Vector3(Radius));
                case ShapeType.Box:
                    return Aabb.Transform(pose, Vector3.Zero, HalfExtents);
                case ShapeType.Capsule:
                {
                    Vector3 axis = pose.TransformDirection(new Vector3(0, HalfHeight, 0));
                    Vector3 e = Vector3.Abs(axis) + new Vector3(Radius);
                    return Aabb.FromCenterExtents(pose.Position, e);
                }
                case ShapeType.Plane:
                    return PlaneAabb(pose);
                default:
                    return Data is IBoundsSource b ? b.ComputeAabb(pose) : Aabb.FromCenterExtents(pose.Position, Vector3.Zero);
            }
        }

        Aabb PlaneAabb(in Pose pose)
        {
            // A half-space is unbounded; a large finite box keeps tree arithmetic finite.
            const float big = 1e6f;
            Vector3 n = pose.TransformDirection(Normal);
            Vector3 min = new Vector3(-big), max = new Vector3(big);
            // Where the normal is an axis, the box can be tight on the solid side's surface.
            Vector3 p = pose.TransformPoint(Normal * Offset);
            if (MathF.Abs(n.Y) > 0.9999f) { if (n.Y > 0) max.Y = p.Y; else min.Y = p.Y; }
            else if (MathF.Abs(n.X) > 0.9999f) { if (n.X > 0) max.X = p.X; else min.X = p.X; }
            else if (MathF.Abs(n.Z) > 0.9999f) { if (n.Z > 0) max.Z = p.Z; else min.Z = p.Z; }
            return new Aabb(min, max);
        }

        /// <inheritdoc/>
        public override string ToString() => Type switch
        {
            ShapeType.Sphere => $"sphere(r={Radius})",
            ShapeType.Box => $"box(h={HalfExtents})",
            ShapeType.Capsule => $"capsule(r={Radius}, h={HalfHeight})",
            ShapeType.Plane => $"plane(n={Normal}, d={Offset})",
            ShapeType.ConvexHull when Data is ConvexHull h => $"hull({h.VertexCount} vertices, {h.FaceCount} faces)",
            ShapeType.TriangleMesh when Data is TriangleMesh m => $"mesh({m.TriangleCount} triangles)",
            _ => Type.ToString(),
        };
    }

    /// <summary>Geometry data that can compute its own mass properties (convex hulls).</summary>
    public interface IMassSource
    {
        /// <summary>Mass properties at <paramref name="density"/> kg/m^3 in the shape frame.</summary>
        MassProperties ComputeMass(float density);
    }

    /// <summary>Geometry data that can compute its own world bounds (hulls and meshes).</summary>
    public interface IBoundsSource
    {
        /// <summary>The world bounds at <paramref name="pose"/>.</summary>
        Aabb ComputeAabb(in Pose pose);
    }
}
