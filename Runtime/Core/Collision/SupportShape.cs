using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// A convex shape placed in the world, described by its core (point, segment, box, hull
    /// vertices, triangle) and a radius around it: sphere = point + r, capsule = segment + r,
    /// the rest have radius 0. GJK, EPA, time of impact and shape casts work on cores and add
    /// radii at the end, which keeps them exact for rounded shapes.
    /// </summary>
    internal struct SupportShape
    {
        public SupportKind Kind;
        public Vector3 Center;          // point; box, hull pose position
        public Mat3 Axes;               // box and hull rotation
        public Vector3 Extent;          // box half-extents
        public Vector3 A, B, C;         // segment ends, triangle vertices (world)
        public ConvexHull? Hull;
        public float Radius;

        /// <summary>The core and radius of a shape geometry at a world pose (planes and meshes have none).</summary>
        public static SupportShape From(in ShapeGeometry g, in Pose pose)
        {
            var s = new SupportShape { Center = pose.Position };
            switch (g.Type)
            {
                case ShapeType.Sphere:
                    s.Kind = SupportKind.Point;
                    s.A = pose.Position;
                    s.Radius = g.Radius;
                    break;
                case ShapeType.Capsule:
                {
                    s.Kind = SupportKind.Segment;
                    Vector3 axis = pose.TransformDirection(new Vector3(0, g.HalfHeight, 0));
                    s.A = pose.Position - axis;
                    s.B = pose.Position + axis;
                    s.Radius = g.Radius;
                    break;
                }
                case ShapeType.Box:
                    s.Kind = SupportKind.Box;
                    s.Axes = Mat3.FromQuaternion(pose.Rotation);
                    s.Extent = g.HalfExtents;
                    break;
                case ShapeType.ConvexHull:
                    s.Kind = SupportKind.Polytope;
                    s.Axes = Mat3.FromQuaternion(pose.Rotation);
                    s.Hull = (ConvexHull)g.Data!;
                    break;
                default:
                    throw new System.ArgumentException($"{g.Type} has no convex core.", nameof(g));
            }
            return s;
        }

        /// <summary>A triangle with no radius.</summary>
        public static SupportShape Triangle(Vector3 a, Vector3 b, Vector3 c) =>
            new SupportShape { Kind = SupportKind.Triangle, A = a, B = b, C = c, Center = (a + b + c) / 3f };

        /// <summary>A point with a radius (a sphere).</summary>
        public static SupportShape Sphere(Vector3 center, float radius) =>
            new SupportShape { Kind = SupportKind.Point, A = center, Center = center, Radius = radius };

        /// <summary>A segment with a radius (a capsule).</summary>
        public static SupportShape Capsule(Vector3 a, Vector3 b, float radius) =>
            new SupportShape { Kind = SupportKind.Segment, A = a, B = b, Center = 0.5f * (a + b), Radius = radius };

        /// <summary>The core point farthest along <paramref name="d"/> and its vertex index.</summary>
        public readonly Vector3 Support(Vector3 d, out int index)
        {
            switch (Kind)
            {
                case SupportKind.Point:
                    index = 0;
                    return A;
                case SupportKind.Segment:
                    if (Vector3.Dot(B - A, d) > 0) { index = 1; return B; }
                    index = 0;
                    return A;
                case SupportKind.Box:
                {
                    Vector3 l = Axes.TransposeMultiply(d);
                    index = (l.X >= 0 ? 1 : 0) | (l.Y >= 0 ? 2 : 0) | (l.Z >= 0 ? 4 : 0);
                    return Vertex(index);
                }
                case SupportKind.Polytope:
                {
                    index = Hull!.SupportIndex(Axes.TransposeMultiply(d));
                    return Vertex(index);
                }
                default:
                {
                    float da = Vector3.Dot(A, d), db = Vector3.Dot(B, d), dc = Vector3.Dot(C, d);
                    if (da >= db && da >= dc) { index = 0; return A; }
                    if (db >= dc) { index = 1; return B; }
                    index = 2;
                    return C;
                }
            }
        }

        /// <summary>Core vertex <paramref name="index"/> in world space.</summary>
        public readonly Vector3 Vertex(int index)
        {
            switch (Kind)
            {
                case SupportKind.Point: return A;
                case SupportKind.Segment: return index == 0 ? A : B;
                case SupportKind.Box:
                {
                    Vector3 e = Extent;
                    Vector3 l = new Vector3((index & 1) != 0 ? e.X : -e.X, (index & 2) != 0 ? e.Y : -e.Y, (index & 4) != 0 ? e.Z : -e.Z);
                    return Center + Axes * l;
                }
                case SupportKind.Polytope: return Center + Axes * Hull!.Vertices[index];
                default: return index == 0 ? A : index == 1 ? B : C;
            }
        }

        /// <summary>
        /// The feature of the core that faces direction <paramref name="n"/> most: a polygon
        /// (box or hull face, triangle) counter-clockwise about its outward
        /// <paramref name="faceNormal"/>, a segment (a capsule lying across n) or a point.
        /// Returns the vertex count (at most the span's length) and an id of the feature.
        /// </summary>
        public readonly int SupportFace(Vector3 n, Span<Vector3> vertices, out Vector3 faceNormal, out int faceId)
        {
            switch (Kind)
            {
                case SupportKind.Point:
                    vertices[0] = A;
                    faceNormal = n;
                    faceId = 0;
                    return 1;
                case SupportKind.Segment:
                {
                    Vector3 d = B - A;
                    float len = d.Length();
                    faceNormal = n;
                    if (len > 1e-6f && MathF.Abs(Vector3.Dot(d, n)) < 0.05f * len * n.Length())
                    {
                        vertices[0] = A;
                        vertices[1] = B;
                        faceId = 0;
                        return 2;
                    }
                    vertices[0] = Support(n, out int end);
                    faceId = 1 + end;
                    return 1;
                }
                case SupportKind.Box:
                {
                    Vector3 l = Axes.TransposeMultiply(n);
                    Vector3 al = Vector3.Abs(l);
                    int k = al.X >= al.Y && al.X >= al.Z ? 0 : al.Y >= al.Z ? 1 : 2;
                    float sign = (k == 0 ? l.X : k == 1 ? l.Y : l.Z) >= 0 ? 1f : -1f;
                    Vector3 axisK = k == 0 ? Axes.C0 : k == 1 ? Axes.C1 : Axes.C2;
                    Vector3 axisU = k == 0 ? Axes.C1 : k == 1 ? Axes.C2 : Axes.C0;
                    Vector3 axisV = k == 0 ? Axes.C2 : k == 1 ? Axes.C0 : Axes.C1;
                    float hk = k == 0 ? Extent.X : k == 1 ? Extent.Y : Extent.Z;
                    float hu = k == 0 ? Extent.Y : k == 1 ? Extent.Z : Extent.X;
                    float hv = k == 0 ? Extent.Z : k == 1 ? Extent.X : Extent.Y;
                    faceNormal = axisK * sign;
                    Vector3 c = Center + faceNormal * hk, u = axisU * hu, v = axisV * (hv * sign);
                    // u x v = sign * axisK: counter-clockwise about the outward normal.
                    vertices[0] = c + u + v;
                    vertices[1] = c - u + v;
                    vertices[2] = c - u - v;
                    vertices[3] = c + u - v;
                    faceId = 2 * k + (sign > 0 ? 0 : 1);
                    return 4;
                }
                case SupportKind.Polytope:
                {
                    ConvexHull h = Hull!;
                    int f = h.SupportFace(Axes.TransposeMultiply(n));
                    faceNormal = Axes * h.FaceNormals[f];
                    int start = h.FaceStart[f], count = Math.Min(h.FaceStart[f + 1] - start, vertices.Length);
                    for (int i = 0; i < count; i++) vertices[i] = Center + Axes * h.Vertices[h.FaceVertices[start + i]];
                    faceId = f;
                    return count;
                }
                default:
                {
                    Vector3 tn = Vector3.Cross(B - A, C - A);
                    float len = tn.Length();
                    faceNormal = len > 0 ? tn / len : n;
                    faceId = 0;
                    if (Vector3.Dot(faceNormal, n) >= 0)
                    {
                        vertices[0] = A; vertices[1] = B; vertices[2] = C;
                    }
                    else
                    {
                        faceNormal = -faceNormal;
                        faceId = 1;
                        vertices[0] = A; vertices[1] = C; vertices[2] = B;
                    }
                    return 3;
                }
            }
        }

        /// <summary>Any point of the core (a start for GJK).</summary>
        public readonly Vector3 AnyPoint => Kind == SupportKind.Box || Kind == SupportKind.Polytope ? Vertex(0) : A;

        /// <summary>The world bounds of the core plus radius.</summary>
        public readonly Aabb Bounds()
        {
            Vector3 hi = new Vector3(Support(Vector3.UnitX, out _).X, Support(Vector3.UnitY, out _).Y, Support(Vector3.UnitZ, out _).Z);
            Vector3 lo = new Vector3(Support(-Vector3.UnitX, out _).X, Support(-Vector3.UnitY, out _).Y, Support(-Vector3.UnitZ, out _).Z);
            return new Aabb(lo - new Vector3(Radius), hi + new Vector3(Radius));
        }
    }
}
