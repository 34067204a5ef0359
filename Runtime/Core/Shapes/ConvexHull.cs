using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    /// <summary>
    /// An immutable convex polyhedron in its shape frame, built from a point cloud by
    /// <see cref="Create"/> (quickhull; duplicate, coplanar and interior points are dropped,
    /// coplanar triangles merged into polygon faces). Faces are vertex loops counter-clockwise
    /// seen from outside with outward unit normals. Share one hull between many shapes.
    /// </summary>
    public sealed class ConvexHull : IMassSource, IBoundsSource
    {
        internal readonly Vector3[] Vertices;
        internal readonly Vector3[] FaceNormals;
        internal readonly float[] FaceOffsets;     // n . x = offset on the face
        internal readonly int[] FaceStart;         // face f uses FaceVertices[FaceStart[f] .. FaceStart[f + 1])
        internal readonly int[] FaceVertices;
        internal readonly int[] EdgeVertices;      // edge e joins EdgeVertices[2e] and [2e + 1]

        // Mass properties at unit density about the centroid (computed once, in double).
        readonly float _volume;
        readonly Vector3 _centroid;
        readonly Mat3 _unitInertia;

        ConvexHull(List<Vec3d> vertices, List<int[]> faces)
        {
            Vertices = new Vector3[vertices.Count];
            for (int i = 0; i < vertices.Count; i++) Vertices[i] = vertices[i].ToVector3();
            FaceNormals = new Vector3[faces.Count];
            FaceOffsets = new float[faces.Count];
            FaceStart = new int[faces.Count + 1];
            var fv = new List<int>();
            var edges = new List<int>();
            var seen = new HashSet<long>();
            for (int f = 0; f < faces.Count; f++)
            {
                int[] loop = faces[f];
                FaceStart[f] = fv.Count;
                fv.AddRange(loop);
                // Newell's normal: robust for polygons with nearly collinear vertices.
                Vec3d n = new Vec3d(0, 0, 0);
                for (int i = 0; i < loop.Length; i++)
                {
                    Vec3d a = vertices[loop[i]], b = vertices[loop[(i + 1) % loop.Length]];
                    n += new Vec3d((a.Y - b.Y) * (a.Z + b.Z), (a.Z - b.Z) * (a.X + b.X), (a.X - b.X) * (a.Y + b.Y));
                    int lo = Math.Min(loop[i], loop[(i + 1) % loop.Length]), hi = Math.Max(loop[i], loop[(i + 1) % loop.Length]);
                    if (seen.Add(((long)lo << 32) | (uint)hi)) { edges.Add(lo); edges.Add(hi); }
                }
                n = n.Normalized;
                // The supporting plane: every vertex on or below it.
                double offset = double.MinValue;
                foreach (Vec3d v in vertices) offset = Math.Max(offset, Vec3d.Dot(n, v));
                FaceNormals[f] = n.ToVector3();
                FaceOffsets[f] = (float)offset;
            }
            FaceStart[faces.Count] = fv.Count;
            FaceVertices = fv.ToArray();
            EdgeVertices = edges.ToArray();
            ComputeUnitMass(vertices, faces, out _volume, out _centroid, out _unitInertia);
        }

        // A hull exactly as saved by WriteState (see World.SaveState).
        ConvexHull(Vector3[] vertices, Vector3[] faceNormals, float[] faceOffsets, int[] faceStart, int[] faceVertices, int[] edgeVertices,
            float volume, Vector3 centroid, Mat3 unitInertia)
        {
            Vertices = vertices;
            FaceNormals = faceNormals;
            FaceOffsets = faceOffsets;
            FaceStart = faceStart;
            FaceVertices = faceVertices;
            EdgeVertices = edgeVertices;
            _volume = volume;
            _centroid = centroid;
            _unitInertia = unitInertia;
        }

        /// <summary>Writes every array and the unit mass properties, so that a restored hull is the same hull bit for bit.</summary>
        internal void WriteState(StateWriter w)
        {
            w.WriteArray(Vertices);
            w.WriteArray(FaceNormals);
            w.WriteArray(FaceOffsets);
            w.WriteArray(FaceStart);
            w.WriteArray(FaceVertices);
            w.WriteArray(EdgeVertices);
            w.Write(_volume);
            w.Write(_centroid);
            w.Write(_unitInertia);
        }

        /// <summary>Reads what <see cref="WriteState"/> wrote, checking every index.</summary>
        internal static ConvexHull ReadState(StateReader r)
        {
            Vector3[] vertices = r.ReadArray<Vector3>("hull vertices");
            Vector3[] normals = r.ReadArray<Vector3>("hull face normals");
            float[] offsets = r.ReadArrayExactly<float>("hull face offsets", normals.Length);
            int[] faceStart = r.ReadArrayExactly<int>("hull face starts", normals.Length + 1);
            int[] faceVertices = r.ReadArray<int>("hull face vertices");
            int[] edges = r.ReadArray<int>("hull edges");
            float volume = r.Read<float>("hull volume");
            Vector3 centroid = r.Read<Vector3>("hull centroid");
            Mat3 inertia = r.Read<Mat3>("hull inertia");
            if (vertices.Length < 4 || normals.Length < 4 || faceStart[0] != 0 || faceStart[normals.Length] != faceVertices.Length)
                throw r.Error("a hull's faces do not match its vertex lists.");
            for (int f = 0; f < normals.Length; f++)
                if (faceStart[f + 1] - faceStart[f] < 3) throw r.Error($"hull face {f} has fewer than 3 vertices.");
            foreach (int v in faceVertices) if ((uint)v >= (uint)vertices.Length) throw r.Error($"a hull face uses vertex {v} of {vertices.Length}.");
            foreach (int v in edges) if ((uint)v >= (uint)vertices.Length) throw r.Error($"a hull edge uses vertex {v} of {vertices.Length}.");
            if (edges.Length % 2 != 0) throw r.Error("a hull edge list has an odd length.");
            return new ConvexHull(vertices, normals, offsets, faceStart, faceVertices, edges, volume, centroid, inertia);
        }

        /// <summary>
        /// Builds the convex hull of a point cloud (shape frame, metres). Throws an
        /// <see cref="ArgumentException"/> naming "hull.points" when a point is not finite or
        /// the cloud has fewer than 4 non-coplanar points (all equal, collinear or coplanar), has
        /// more than <see cref="Limits.MaxHullPoints"/> points, or a coordinate beyond
        /// <see cref="Limits.MaxShapeSize"/>.
        /// </summary>
        public static ConvexHull Create(ReadOnlySpan<Vector3> points)
        {
            if (points.Length > Limits.MaxHullPoints)
                throw new ArgumentException($"hull.points has {points.Length} points; at most {Limits.MaxHullPoints} (Limits.MaxHullPoints) are taken.", "hull.points");
            for (int i = 0; i < points.Length; i++)
            {
                Vector3 p = points[i];
                if (Math.Abs(p.X) > Limits.MaxShapeSize || Math.Abs(p.Y) > Limits.MaxShapeSize || Math.Abs(p.Z) > Limits.MaxShapeSize)
                    throw new ArgumentException($"hull.points[{i}] must lie within +-{Limits.MaxShapeSize:G} m (Limits.MaxShapeSize), got {p}.", "hull.points");
            }
            QuickHull.Build(points, "hull.points", out List<Vec3d> vertices, out List<int[]> faces, out _);
            return new ConvexHull(vertices, faces);
        }

        /// <summary>Number of vertices.</summary>
        public int VertexCount => Vertices.Length;

        /// <summary>Number of faces (planar polygons).</summary>
        public int FaceCount => FaceNormals.Length;

        /// <summary>Number of edges.</summary>
        public int EdgeCount => EdgeVertices.Length / 2;

        /// <summary>Vertex <paramref name="i"/> in the shape frame, metres.</summary>
        public Vector3 GetVertex(int i) => Vertices[i];

        /// <summary>The outward unit normal of face <paramref name="f"/>.</summary>
        public Vector3 GetFaceNormal(int f) => FaceNormals[f];

        /// <summary>The vertex indices of face <paramref name="f"/>, counter-clockwise seen from outside.</summary>
        public ReadOnlySpan<int> GetFace(int f) => new ReadOnlySpan<int>(FaceVertices, FaceStart[f], FaceStart[f + 1] - FaceStart[f]);

        /// <summary>The enclosed volume, m^3.</summary>
        public float Volume => _volume;

        /// <summary>The centroid (centre of mass at uniform density) in the shape frame, metres.</summary>
        public Vector3 Centroid => _centroid;

        /// <summary>Exact mass properties of the solid polyhedron at <paramref name="density"/> kg/m^3.</summary>
        public MassProperties ComputeMass(float density) => new MassProperties(density * _volume, _centroid, _unitInertia * density);

        /// <summary>The tight world bounds at a pose (support points along the world axes).</summary>
        public Aabb ComputeAabb(in Pose pose)
        {
            Mat3 r = Mat3.FromQuaternion(pose.Rotation);
            Vector3 hi = new Vector3(
                Vector3.Dot(r * Vertices[SupportIndex(r.R0)], Vector3.UnitX),
                Vector3.Dot(r * Vertices[SupportIndex(r.R1)], Vector3.UnitY),
                Vector3.Dot(r * Vertices[SupportIndex(r.R2)], Vector3.UnitZ));
            Vector3 lo = new Vector3(
                Vector3.Dot(r * Vertices[SupportIndex(-r.R0)], Vector3.UnitX),
                Vector3.Dot(r * Vertices[SupportIndex(-r.R1)], Vector3.UnitY),
                Vector3.Dot(r * Vertices[SupportIndex(-r.R2)], Vector3.UnitZ));
            return new Aabb(pose.Position + lo, pose.Position + hi);
        }

        /// <summary>The vertex farthest along a direction in the shape frame.</summary>
        internal int SupportIndex(Vector3 direction) => Farthest(Vertices, direction);

        /// <summary>The face whose outward normal is most aligned with a shape-frame direction.</summary>
        internal int SupportFace(Vector3 direction) => Farthest(FaceNormals, direction);

        // The index of the vector with the largest dot product with the direction (the first on a tie).
        static int Farthest(Vector3[] vectors, Vector3 direction)
        {
            int best = 0;
            float max = Vector3.Dot(vectors[0], direction);
            for (int i = 1; i < vectors.Length; i++)
            {
                float d = Vector3.Dot(vectors[i], direction);
                if (d > max) { max = d; best = i; }
            }
            return best;
        }

        // Volume, centroid and inertia at unit density by summing signed tetrahedra from a
        // reference point over a fan triangulation of each face. Each tetrahedron's second
        // moment is det(A)/120 (A C A^T) with A = [a b c] and C = [[2,1,1],[1,2,1],[1,1,2]]
        // (Tonon, "Explicit exact formulas for the 3-D tetrahedron inertia tensor", 2004);
        // the inertia is tr(S) E - S of the covariance S moved to the centroid.
        static void ComputeUnitMass(List<Vec3d> v, List<int[]> faces, out float volume, out Vector3 centroid, out Mat3 inertia)
        {
            Vec3d origin = new Vec3d(0, 0, 0);
            foreach (Vec3d p in v) origin += p;
            origin *= 1.0 / v.Count;

            double vol = 0;
            Vec3d first = new Vec3d(0, 0, 0);
            double sxx = 0, syy = 0, szz = 0, sxy = 0, sxz = 0, syz = 0;
            foreach (int[] f in faces)
            {
                Vec3d a = v[f[0]] - origin;
                for (int i = 1; i + 1 < f.Length; i++)
                {
                    Vec3d b = v[f[i]] - origin, c = v[f[i + 1]] - origin;
                    double det = Vec3d.Dot(a, Vec3d.Cross(b, c));
                    vol += det / 6;
                    first += (a + b + c) * (det / 24);
                    double k = det / 120;
                    sxx += k * (Sq(a.X, b.X, c.X));
                    syy += k * (Sq(a.Y, b.Y, c.Y));
                    szz += k * (Sq(a.Z, b.Z, c.Z));
                    sxy += k * Mixed(a.X, b.X, c.X, a.Y, b.Y, c.Y);
                    sxz += k * Mixed(a.X, b.X, c.X, a.Z, b.Z, c.Z);
                    syz += k * Mixed(a.Y, b.Y, c.Y, a.Z, b.Z, c.Z);
                }
            }
            Vec3d cm = first * (1 / vol);
            // Parallel-axis shift of the covariance from the reference point to the centroid.
            sxx -= vol * cm.X * cm.X; syy -= vol * cm.Y * cm.Y; szz -= vol * cm.Z * cm.Z;
            sxy -= vol * cm.X * cm.Y; sxz -= vol * cm.X * cm.Z; syz -= vol * cm.Y * cm.Z;
            double tr = sxx + syy + szz;
            inertia = Mat3.FromRows(
                new Vector3((float)(tr - sxx), (float)-sxy, (float)-sxz),
                new Vector3((float)-sxy, (float)(tr - syy), (float)-syz),
                new Vector3((float)-sxz, (float)-syz, (float)(tr - szz)));
            volume = (float)vol;
            centroid = (cm + origin).ToVector3();
        }

        // (a b c) C (a b c)^T for one coordinate, and the mixed form for two.
        static double Sq(double a, double b, double c) => 2 * (a * a + b * b + c * c) + 2 * (a * b + b * c + c * a);

        static double Mixed(double ax, double bx, double cx, double ay, double by, double cy) =>
            2 * (ax * ay + bx * by + cx * cy) + ax * by + ay * bx + bx * cy + by * cx + cx * ay + cy * ax;
    }
}
