using System;
using System.Collections.Generic;

namespace Fulcrum
{
    /// <summary>
    /// Quickhull in 3D (Barber, Dobkin and Huhdanpaa, "The quickhull algorithm for convex
    /// hulls", 1996), in double precision with a tolerance: a point within the tolerance of a
    /// face counts as on it, so duplicate and coplanar points never become vertices of their
    /// own. The horizon is found by a depth-first walk over the visible faces that emits its
    /// edges in order (Gregorius, "Implementing Quickhull", GDC 2014). The triangles are then
    /// merged into planar polygons: neighbours join a face while all their vertices lie within
    /// the tolerance of its plane, which also absorbs sliver triangles whose own normals are
    /// meaningless. Runs once per hull (allocates freely; never in a step).
    /// </summary>
    internal sealed class QuickHull
    {
        sealed class Face
        {
            public readonly int[] V = new int[3];
            public readonly Face?[] Neighbor = new Face?[3];
            public Vec3d Normal;
            public double Offset;
            public double Area;
            public readonly List<int> Outside = new List<int>();
            public bool Dead;
            public int Mark;
            public int Group = -1;
        }

        readonly Vec3d[] _p;
        readonly double _tolerance;
        readonly List<Face> _faces = new List<Face>();
        readonly List<(Face face, int edge)> _horizon = new List<(Face, int)>();
        readonly List<Face> _visible = new List<Face>();
        int _mark;

        QuickHull(Vec3d[] points, double tolerance)
        {
            _p = points;
            _tolerance = tolerance;
        }

        /// <summary>
        /// The hull of <paramref name="points"/> as vertices and counter-clockwise polygon
        /// faces. Throws <see cref="ArgumentException"/> (naming <paramref name="name"/>) for
        /// non-finite points or clouds with fewer than four non-coplanar points.
        /// </summary>
        public static void Build(ReadOnlySpan<System.Numerics.Vector3> points, string name,
            out List<Vec3d> vertices, out List<int[]> faces, out double tolerance)
        {
            if (points.Length < 4)
                throw new ArgumentException($"{name} needs at least 4 non-coplanar points, got {points.Length}.", name);
            var p = new Vec3d[points.Length];
            double maxAbsX = 0, maxAbsY = 0, maxAbsZ = 0;
            for (int i = 0; i < points.Length; i++)
            {
                var v = points[i];
                if (!(float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z)))
                    throw new ArgumentException($"{name}[{i}] must be finite, got {v}.", name);
                p[i] = new Vec3d(v.X, v.Y, v.Z);
                maxAbsX = Math.Max(maxAbsX, Math.Abs(v.X));
                maxAbsY = Math.Max(maxAbsY, Math.Abs(v.Y));
                maxAbsZ = Math.Max(maxAbsZ, Math.Abs(v.Z));
            }
            // The points come from floats: their coordinates are only good to a float ulp of
            // the largest coordinate, so anything closer to a plane than a few of those is on it.
            tolerance = 8 * 1.2e-7 * (maxAbsX + maxAbsY + maxAbsZ);
            var hull = new QuickHull(p, tolerance);
            hull.Run(name);
            hull.Merge(out vertices, out faces);
        }

        void Run(string name)
        {
            int[] tet = InitialTetrahedron(name);
            var used = new bool[_p.Length];
            foreach (int i in tet) used[i] = true;
            for (int i = 0; i < _p.Length; i++)
                if (!used[i]) Assign(i, _faces);

            while (true)
            {
                Face? face = null;
                foreach (Face f in _faces)
                    if (!f.Dead && f.Outside.Count > 0) { face = f; break; }
                if (face == null) break;
                int eye = Farthest(face);
                AddPoint(eye, face);
            }
            _faces.RemoveAll(f => f.Dead);
        }

        int[] InitialTetrahedron(string name)
        {
            int n = _p.Length;
            // Extreme points on the axes, then the farthest pair of them.
            var extremes = new int[6];
            for (int i = 0; i < n; i++)
            {
                Vec3d v = _p[i];
                if (v.X < _p[extremes[0]].X) extremes[0] = i;
                if (v.X > _p[extremes[1]].X) extremes[1] = i;
                if (v.Y < _p[extremes[2]].Y) extremes[2] = i;
                if (v.Y > _p[extremes[3]].Y) extremes[3] = i;
                if (v.Z < _p[extremes[4]].Z) extremes[4] = i;
                if (v.Z > _p[extremes[5]].Z) extremes[5] = i;
            }
            int a = extremes[0], b = extremes[1];
            double best = -1;
            for (int i = 0; i < 6; i++)
                for (int j = i + 1; j < 6; j++)
                {
                    double d = (_p[extremes[i]] - _p[extremes[j]]).LengthSquared;
                    if (d > best) { best = d; a = extremes[i]; b = extremes[j]; }
                }
            if (Math.Sqrt(best) <= _tolerance)
                throw new ArgumentException($"{name}: all points coincide; a hull needs at least 4 non-coplanar points.", name);

            Vec3d ab = _p[b] - _p[a];
            int c = -1;
            best = -1;
            for (int i = 0; i < n; i++)
            {
                double d = Vec3d.Cross(ab, _p[i] - _p[a]).LengthSquared;
                if (d > best) { best = d; c = i; }
            }
            if (Math.Sqrt(best) / ab.Length <= _tolerance)
                throw new ArgumentException($"{name}: all points are collinear; a hull needs at least 4 non-coplanar points.", name);

            Vec3d normal = Vec3d.Cross(ab, _p[c] - _p[a]).Normalized;
            int d4 = -1;
            best = -1;
            for (int i = 0; i < n; i++)
            {
                double d = Math.Abs(Vec3d.Dot(normal, _p[i] - _p[a]));
                if (d > best) { best = d; d4 = i; }
            }
            if (best <= _tolerance)
                throw new ArgumentException($"{name}: all points are coplanar; a hull needs at least 4 non-coplanar points.", name);

            // Orient so that d4 lies below the base triangle (a, b, c).
            if (Vec3d.Dot(normal, _p[d4] - _p[a]) > 0) (b, c) = (c, b);
            Face f0 = MakeFace(a, b, c), f1 = MakeFace(a, d4, b), f2 = MakeFace(b, d4, c), f3 = MakeFace(c, d4, a);
            Link(f0, 0, f1, 2); Link(f0, 1, f2, 2); Link(f0, 2, f3, 2);
            Link(f1, 1, f2, 0); Link(f2, 1, f3, 0); Link(f3, 1, f1, 0);
            return new[] { a, b, c, d4 };
        }

        Face MakeFace(int a, int b, int c)
        {
            var f = new Face();
            f.V[0] = a;
            f.V[1] = b;
            f.V[2] = c;
            Vec3d n = Vec3d.Cross(_p[b] - _p[a], _p[c] - _p[a]);
            double len = n.Length;
            f.Area = 0.5 * len;
            f.Normal = len > 0 ? n * (1 / len) : new Vec3d(0, 0, 0);
            f.Offset = Vec3d.Dot(f.Normal, (_p[a] + _p[b] + _p[c]) * (1.0 / 3));
            _faces.Add(f);
            return f;
        }

        static void Link(Face f, int edge, Face g, int gEdge)
        {
            f.Neighbor[edge] = g;
            g.Neighbor[gEdge] = f;
        }

        double Distance(Face f, int point) => Vec3d.Dot(f.Normal, _p[point]) - f.Offset;

        void Assign(int point, List<Face> candidates)
        {
            Face? best = null;
            double bestD = _tolerance;
            foreach (Face f in candidates)
            {
                if (f.Dead) continue;
                double d = Distance(f, point);
                if (d > bestD) { bestD = d; best = f; }
            }
            best?.Outside.Add(point);
        }

        int Farthest(Face f)
        {
            int best = f.Outside[0];
            double bestD = Distance(f, best);
            foreach (int i in f.Outside)
            {
                double d = Distance(f, i);
                if (d > bestD) { bestD = d; best = i; }
            }
            return best;
        }

        void AddPoint(int eye, Face start)
        {
            _mark++;
            _horizon.Clear();
            _visible.Clear();
            FindHorizon(eye, start, -1);

            var created = new List<Face>(_horizon.Count);
            foreach (var (face, edge) in _horizon)
            {
                int a = face.V[edge], b = face.V[(edge + 1) % 3];
                Face across = face.Neighbor[edge]!;
                Face nf = MakeFace(a, b, eye);
                int back = Array.IndexOf(across.Neighbor, face);
                Link(nf, 0, across, back);
                created.Add(nf);
            }
            // The horizon is a closed loop in order: new face k meets new face k + 1 on (b, eye).
            for (int k = 0; k < created.Count; k++)
            {
                Face f = created[k], g = created[(k + 1) % created.Count];
                if (f.V[1] != g.V[0]) throw new InvalidOperationException("quickhull: horizon out of order");
                Link(f, 1, g, 2);
            }
            foreach (Face v in _visible)
            {
                v.Dead = true;
                foreach (int i in v.Outside)
                    if (i != eye) Assign(i, created);
                v.Outside.Clear();
            }
        }

        // Depth-first over faces that see the eye, entering each across an edge and leaving
        // through the next two in order, so horizon edges come out as a counter-clockwise loop.
        void FindHorizon(int eye, Face face, int enteredEdge)
        {
            face.Mark = _mark;
            _visible.Add(face);
            for (int k = 0; k < 3; k++)
            {
                int edge = enteredEdge < 0 ? k : (enteredEdge + 1 + k) % 3;
                if (enteredEdge >= 0 && k == 2) break;
                Face n = face.Neighbor[edge]!;
                if (n.Mark == _mark) continue;
                if (Distance(n, eye) > _tolerance)
                    FindHorizon(eye, n, Array.IndexOf(n.Neighbor, face));
                else
                    _horizon.Add((face, edge));
            }
        }

        // Groups coplanar triangles (largest first) into polygons and walks each group's
        // boundary into a counter-clockwise vertex loop.
        void Merge(out List<Vec3d> vertices, out List<int[]> faces)
        {
            var order = new List<Face>(_faces);
            order.Sort((x, y) => y.Area.CompareTo(x.Area));
            var groups = new List<List<Face>>();
            var queue = new Queue<Face>();
            foreach (Face seed in order)
            {
                if (seed.Group >= 0) continue;
                var members = new List<Face>();
                int id = groups.Count;
                groups.Add(members);
                seed.Group = id;
                queue.Enqueue(seed);
                while (queue.Count > 0)
                {
                    Face f = queue.Dequeue();
                    members.Add(f);
                    foreach (Face? n in f.Neighbor)
                    {
                        if (n == null || n.Group >= 0) continue;
                        if (!OnPlane(seed, n)) continue;
                        n.Group = id;
                        queue.Enqueue(n);
                    }
                }
            }

            var remap = new Dictionary<int, int>();
            vertices = new List<Vec3d>();
            faces = new List<int[]>();
            foreach (var members in groups)
            {
                // Boundary edges a -> b (counter-clockwise) of the group.
                var next = new Dictionary<int, int>();
                int startVertex = -1;
                foreach (Face f in members)
                    for (int e = 0; e < 3; e++)
                    {
                        Face n = f.Neighbor[e]!;
                        if (n.Group == f.Group) continue;
                        next[f.V[e]] = f.V[(e + 1) % 3];
                        if (startVertex < 0) startVertex = f.V[e];
                    }
                var loop = new List<int>();
                int v = startVertex;
                do
                {
                    loop.Add(v);
                    if (!next.TryGetValue(v, out v) || loop.Count > next.Count) throw new InvalidOperationException("quickhull: open face boundary");
                } while (v != startVertex);

                var face = new int[loop.Count];
                for (int i = 0; i < loop.Count; i++)
                {
                    if (!remap.TryGetValue(loop[i], out int r))
                    {
                        r = vertices.Count;
                        remap[loop[i]] = r;
                        vertices.Add(_p[loop[i]]);
                    }
                    face[i] = r;
                }
                faces.Add(face);
            }
        }

        bool OnPlane(Face seed, Face f)
        {
            if (f.Area > _tolerance * _tolerance && Vec3d.Dot(seed.Normal, f.Normal) < 0.5) return false;
            for (int i = 0; i < 3; i++)
                if (Math.Abs(Distance(seed, f.V[i])) > _tolerance) return false;
            return true;
        }
    }
}
