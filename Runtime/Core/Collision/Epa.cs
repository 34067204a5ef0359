using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The expanding polytope algorithm (van den Bergen, "Proximity queries and penetration
    /// depth computation on 3D game objects", GDC 2001): starting from a tetrahedron of the
    /// Minkowski difference A - B that holds the origin, repeatedly split the face nearest the
    /// origin with the support point along its normal until that face is on the boundary.
    /// Its normal is the direction of least penetration (from A to B) and its distance the
    /// depth. Works on cores (radii are the caller's). Scratch memory is per thread, sized
    /// once; nothing is allocated after the first call on a thread.
    /// </summary>
    internal static class Epa
    {
        const int MaxVertices = 96;
        const int MaxFaces = 192;
        const int MaxIterations = 64;

        sealed class Workspace
        {
            public readonly SimplexVertex[] Vertices = new SimplexVertex[MaxVertices];
            public readonly int[] FaceA = new int[MaxFaces], FaceB = new int[MaxFaces], FaceC = new int[MaxFaces];
            public readonly Vector3[] FaceNormal = new Vector3[MaxFaces];
            public readonly float[] FaceDistance = new float[MaxFaces];
            public readonly bool[] FaceAlive = new bool[MaxFaces];
            public readonly int[] EdgeFrom = new int[MaxFaces * 3], EdgeTo = new int[MaxFaces * 3];
            public int VertexCount, FaceCount, EdgeCount;
        }

        [ThreadStatic] static Workspace? t_workspace;

        /// <summary>
        /// Penetration of the cores whose GJK run ended in <paramref name="simplex"/> (which
        /// found them overlapping). False when the difference is flat (two segments or points)
        /// or the numbers degenerate; the caller then picks a normal itself.
        /// </summary>
        public static bool Penetration(in SupportShape a, in SupportShape b, in Simplex simplex,
            out Vector3 normal, out float depth, out Vector3 pointA, out Vector3 pointB)
        {
            Workspace w = t_workspace ??= new Workspace();
            normal = default;
            depth = 0;
            pointA = pointB = default;
            w.VertexCount = 0;
            w.FaceCount = 0;
            for (int i = 0; i < simplex.Count; i++) w.Vertices[w.VertexCount++] = simplex.Get(i);
            if (!BuildTetrahedron(a, b, w)) return false;

            float scale = 0;
            for (int i = 0; i < 4; i++) scale = MathF.Max(scale, w.Vertices[i].W.Length());
            float tolerance = 1e-5f * MathF.Max(1f, scale);

            int best = -1;
            for (int iteration = 0; iteration < MaxIterations; iteration++)
            {
                best = -1;
                float bestD = float.MaxValue;
                for (int f = 0; f < w.FaceCount; f++)
                    if (w.FaceAlive[f] && w.FaceDistance[f] < bestD) { bestD = w.FaceDistance[f]; best = f; }
                if (best < 0) return false;

                Vector3 n = w.FaceNormal[best];
                Vector3 sa = a.Support(n, out int ia), sb = b.Support(-n, out int ib);
                var v = new SimplexVertex(sa, ia, sb, ib);
                float d = Vector3.Dot(v.W, n);
                if (d - bestD <= tolerance || w.VertexCount == MaxVertices) break;
                if (!Expand(w, v)) break;
            }
            if (best < 0) return false;

            normal = w.FaceNormal[best];
            depth = MathF.Max(0, w.FaceDistance[best]);
            // Barycentric coordinates of the origin's projection on the face give the witnesses.
            SimplexVertex p = w.Vertices[w.FaceA[best]], q = w.Vertices[w.FaceB[best]], r = w.Vertices[w.FaceC[best]];
            Vector3 x = normal * w.FaceDistance[best];
            Vector3 n2 = Vector3.Cross(q.W - p.W, r.W - p.W);
            float area = Vector3.Dot(n2, n2);
            float u = 1f / 3, v2 = 1f / 3, w2 = 1f / 3;
            if (area > 1e-20f)
            {
                u = Vector3.Dot(Vector3.Cross(q.W - x, r.W - x), n2) / area;
                v2 = Vector3.Dot(Vector3.Cross(r.W - x, p.W - x), n2) / area;
                w2 = 1 - u - v2;
            }
            pointA = p.A * u + q.A * v2 + r.A * w2;
            pointB = p.B * u + q.B * v2 + r.B * w2;
            return true;
        }

        // Grows the GJK simplex to a tetrahedron with outward faces; false when A - B is flat.
        static bool BuildTetrahedron(in SupportShape a, in SupportShape b, Workspace w)
        {
            SimplexVertex[] v = w.Vertices;
            if (w.VertexCount == 1)
            {
                for (int k = 0; k < 6 && w.VertexCount < 2; k++)
                {
                    Vector3 d = Axis(k);
                    SimplexVertex s = Support(a, b, d);
                    if ((s.W - v[0].W).LengthSquared() > 1e-12f) v[w.VertexCount++] = s;
                }
                if (w.VertexCount < 2) return false;
            }
            if (w.VertexCount == 2)
            {
                Vector3 e = v[1].W - v[0].W;
                float bestDist = 0;
                SimplexVertex bestS = default;
                for (int k = 0; k < 6; k++)
                {
                    Vector3 d = Vector3.Cross(e, Axis(k));
                    if (d.LengthSquared() < 1e-12f) continue;
                    SimplexVertex s = Support(a, b, d);
                    float dist = Vector3.Cross(e, s.W - v[0].W).LengthSquared();
                    if (dist > bestDist) { bestDist = dist; bestS = s; }
                }
                if (bestDist <= 1e-12f * MathF.Max(1e-12f, e.LengthSquared())) return false;
                v[w.VertexCount++] = bestS;
            }
            if (w.VertexCount == 3)
            {
                Vector3 n = Vector3.Cross(v[1].W - v[0].W, v[2].W - v[0].W);
                SimplexVertex up = Support(a, b, n), down = Support(a, b, -n);
                float du = MathF.Abs(Vector3.Dot(up.W - v[0].W, n)), dd = MathF.Abs(Vector3.Dot(down.W - v[0].W, n));
                SimplexVertex s = du >= dd ? up : down;
                if (MathF.Max(du, dd) <= 1e-10f * n.Length() * MathF.Max(1e-6f, (v[1].W - v[0].W).Length())) return false;
                v[w.VertexCount++] = s;
            }
            // Orient: the fourth vertex must lie behind face (0, 1, 2).
            Vector3 n012 = Vector3.Cross(v[1].W - v[0].W, v[2].W - v[0].W);
            float side = Vector3.Dot(n012, v[3].W - v[0].W);
            if (MathF.Abs(side) < 1e-12f) return false;
            if (side > 0) (v[1], v[2]) = (v[2], v[1]);
            return AddFace(w, 0, 1, 2) & AddFace(w, 0, 3, 1) & AddFace(w, 1, 3, 2) & AddFace(w, 2, 3, 0);
        }

        static Vector3 Axis(int k) => k switch
        {
            0 => Vector3.UnitX,
            1 => -Vector3.UnitX,
            2 => Vector3.UnitY,
            3 => -Vector3.UnitY,
            4 => Vector3.UnitZ,
            _ => -Vector3.UnitZ,
        };

        static SimplexVertex Support(in SupportShape a, in SupportShape b, Vector3 d)
        {
            Vector3 sa = a.Support(d, out int ia), sb = b.Support(-d, out int ib);
            return new SimplexVertex(sa, ia, sb, ib);
        }

        static bool AddFace(Workspace w, int i0, int i1, int i2)
        {
            if (w.FaceCount == MaxFaces)
            {
                // Reuse a dead slot.
                int slot = -1;
                for (int f = 0; f < MaxFaces; f++) if (!w.FaceAlive[f]) { slot = f; break; }
                if (slot < 0) return false;
                return SetFace(w, slot, i0, i1, i2);
            }
            return SetFace(w, w.FaceCount++, i0, i1, i2);
        }

        static bool SetFace(Workspace w, int f, int i0, int i1, int i2)
        {
            Vector3 p = w.Vertices[i0].W;
            Vector3 n = Vector3.Cross(w.Vertices[i1].W - p, w.Vertices[i2].W - p);
            float len = n.Length();
            w.FaceA[f] = i0;
            w.FaceB[f] = i1;
            w.FaceC[f] = i2;
            w.FaceAlive[f] = true;
            if (len < 1e-20f)
            {
                // A sliver: keep the hole closed, but never pick it as nearest.
                w.FaceNormal[f] = Vector3.UnitX;
                w.FaceDistance[f] = float.MaxValue;
                return true;
            }
            n /= len;
            w.FaceNormal[f] = n;
            w.FaceDistance[f] = Vector3.Dot(n, p);
            return true;
        }

        // Removes the faces the new vertex sees and closes the hole with a fan from it.
        static bool Expand(Workspace w, in SimplexVertex s)
        {
            int vi = w.VertexCount++;
            w.Vertices[vi] = s;
            w.EdgeCount = 0;
            for (int f = 0; f < w.FaceCount; f++)
            {
                if (!w.FaceAlive[f]) continue;
                // Slivers stay: their neighbours' removal leaves their edges on the horizon.
                if (w.FaceDistance[f] == float.MaxValue) continue;
                if (Vector3.Dot(w.FaceNormal[f], s.W - w.Vertices[w.FaceA[f]].W) > 0)
                {
                    w.FaceAlive[f] = false;
                    AddEdge(w, w.FaceA[f], w.FaceB[f]);
                    AddEdge(w, w.FaceB[f], w.FaceC[f]);
                    AddEdge(w, w.FaceC[f], w.FaceA[f]);
                }
            }
            if (w.EdgeCount == 0) return false;
            for (int e = 0; e < w.EdgeCount; e++)
                if (!AddFace(w, w.EdgeFrom[e], w.EdgeTo[e], vi)) return false;
            return true;
        }

        // The horizon: an edge shared by two removed faces cancels; the rest stay, directed
        // as in the removed face, so the new faces wind the same way.
        static void AddEdge(Workspace w, int from, int to)
        {
            for (int e = 0; e < w.EdgeCount; e++)
                if (w.EdgeFrom[e] == to && w.EdgeTo[e] == from)
                {
                    w.EdgeCount--;
                    w.EdgeFrom[e] = w.EdgeFrom[w.EdgeCount];
                    w.EdgeTo[e] = w.EdgeTo[w.EdgeCount];
                    return;
                }
            if (w.EdgeCount == w.EdgeFrom.Length) return;
            w.EdgeFrom[w.EdgeCount] = from;
            w.EdgeTo[w.EdgeCount] = to;
            w.EdgeCount++;
        }
    }
}
