using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Contacts between different soft bodies: each surface vertex of one body against the
    /// surface triangles of the other, both ways. Once per step, for every pair of bodies whose
    /// bounds (padded by the distance they may close over the step) meet, one body's surface
    /// vertices go into a spatial hash with cells as large as the other's largest padded
    /// triangle, and each such triangle collects the vertices in the cells its padded box
    /// covers. After every substep each pair is a zero-compliance XPBD constraint
    /// C = n . (p - (b0 x0 + b1 x1 + b2 x2)) - (r_p + r_t) &gt;= 0, n the face normal and b the
    /// barycentric weights of the vertex's projection onto the face, held fixed; it acts only
    /// while the projection falls on the face (beside it, the neighbouring face or the pairs of
    /// the other direction take over: closest-edge normals there kicked stacked cubes sideways
    /// where one's bottom edge met the other's side). The vertex moves by w_p dl n and triangle vertex k by
    /// -w_k b_k dl n with dl = -C / (w_p + sum b_k^2 w_k): the mass-weighted corrections sum to
    /// zero and momentum is conserved. Coulomb friction then removes the relative tangential
    /// displacement of the substep up to mu times the normal correction, with the same weights
    /// (mu: the mean of the two bodies' <see cref="SoftBody.Friction"/>). Positions and the
    /// velocities already taken from them change together (v += dx / h), as if the correction
    /// came before the velocity update.
    /// Surfaces of volume bodies are one-sided: a triangle acts on a vertex only when the vertex
    /// was in front of it, or less than the contact distance behind, at the start of the
    /// substep, so the far side of a body never pulls a vertex through it. Shell triangles act
    /// from whichever side the vertex came.
    /// </summary>
    internal sealed class SoftSoftContacts
    {
        /// <summary>One vertex of one body against one surface triangle of another.</summary>
        internal struct Pair
        {
            public SoftBody VertexBody;
            public SoftBody TriangleBody;
            public int Vertex;
            public int T0, T1, T2;
            public float Thickness;
            public float Friction;
            /// <summary>
            /// The normal correction a Newton body's step already made on this pair in the
            /// current substep (kg m, as the pass's multipliers; see ImplicitNewtonSolver's soft
            /// contacts): it joins the friction cone of the pass after the substep.
            /// </summary>
            public float Pushed;
        }

        SoftSurface?[] _surfaces = Array.Empty<SoftSurface?>();
        Pair[] _pairs = Array.Empty<Pair>();
        int _count;

        /// <summary>Vertex-triangle pairs found for this step.</summary>
        public int PairCount => _count;

        /// <summary>The pair at <paramref name="index"/> (0 .. PairCount - 1).</summary>
        internal ref Pair this[int index] => ref _pairs[index];

        /// <summary>Finds the vertex-triangle pairs of different bodies that may touch during a step of <paramref name="dt"/>.</summary>
        public void FindPairs(SoftBodySystem bodies, float gravity, float dt)
        {
            _count = 0;
            for (int k = 0; k < bodies.Count; k++) bodies[k].SoftPairs = null;
            if (bodies.Count < 2) return;
            for (int k = 0; k < bodies.Count; k++)
            {
                SoftBody body = bodies[k];
                if (body.CollideWithSoftBodies) SurfaceOf(body).Refresh();
            }
            for (int a = 0; a < bodies.Count; a++)
            {
                SoftBody bodyA = bodies[a];
                if (!bodyA.CollideWithSoftBodies) continue;
                for (int b = a + 1; b < bodies.Count; b++)
                {
                    SoftBody bodyB = bodies[b];
                    if (!bodyB.CollideWithSoftBodies) continue;
                    if ((bodyA.CollidesWith & (1u << bodyB.Layer)) == 0 || (bodyB.CollidesWith & (1u << bodyA.Layer)) == 0) continue;
                    SoftSurface surfaceA = SurfaceOf(bodyA), surfaceB = SurfaceOf(bodyB);
                    float thickness = bodyA.CollisionRadius + bodyB.CollisionRadius;
                    float reach = thickness + (surfaceA.MaxSpeed + surfaceB.MaxSpeed) * dt + gravity * dt * dt + 0.002f;
                    if (!surfaceA.Bounds.Expanded(reach).Overlaps(surfaceB.Bounds)) continue;
                    float friction = 0.5f * (bodyA.Friction + bodyB.Friction);
                    int before = _count;
                    Collect(surfaceA, surfaceB, thickness, reach, friction);
                    Collect(surfaceB, surfaceA, thickness, reach, friction);
                    if (_count > before) bodyA.SoftPairs = bodyB.SoftPairs = this;
                }
            }
        }

        SoftSurface SurfaceOf(SoftBody body)
        {
            if (body.Slot >= _surfaces.Length) Array.Resize(ref _surfaces, Math.Max(4, 2 * body.Slot + 1));
            SoftSurface? surface = _surfaces[body.Slot];
            if (surface == null || surface.Body != body) _surfaces[body.Slot] = surface = new SoftSurface(body);
            return surface;
        }

        /// <summary>Pairs of the vertices of <paramref name="vertices"/> with the triangles of <paramref name="triangles"/>.</summary>
        void Collect(SoftSurface vertices, SoftSurface triangles, float thickness, float reach, float friction)
        {
            Vector3[] xv = vertices.Body.X, xt = triangles.Body.X;
            SpatialHash hash = vertices.Hash;
            hash.Build(xv, vertices.Vertices, vertices.Vertices.Length, triangles.MaxTriangleExtent + 2f * reach);
            Aabb region = vertices.Bounds.Expanded(reach);
            bool oneSided = !triangles.Body.IsShell;
            int[] tris = triangles.Triangles;
            for (int t = 0; t < tris.Length; t += 3)
            {
                Vector3 a = xt[tris[t]], b = xt[tris[t + 1]], c = xt[tris[t + 2]];
                var box = Aabb.OfTriangle(a, b, c).Expanded(reach);
                if (!box.Overlaps(region)) continue;
                Vector3 n = Vector3.Cross(b - a, c - a);
                float area2 = n.Length();
                if (area2 < 1e-12f) continue;
                n /= area2;
                hash.Cell(box.Min, out int x0, out int y0, out int z0);
                hash.Cell(box.Max, out int x1, out int y1, out int z1);
                for (int cz = z0; cz <= z1; cz++)
                    for (int cy = y0; cy <= y1; cy++)
                        for (int cx = x0; cx <= x1; cx++)
                        {
                            int cell = hash.HashCell(cx, cy, cz);
                            for (int k = hash.Start(cell); k < hash.Start(cell + 1); k++)
                            {
                                int i = hash.Entry(k);
                                Vector3 p = xv[i];
                                // A table cell may hold several grid cells; take each vertex from its own cell only.
                                hash.Cell(p, out int px, out int py, out int pz);
                                if (px != cx || py != cy || pz != cz) continue;
                                if (!box.Contains(p)) continue;
                                if (oneSided && Vector3.Dot(n, p - a) < -thickness) continue;
                                if (_count == _pairs.Length) Array.Resize(ref _pairs, Math.Max(64, 2 * _count));
                                _pairs[_count++] = new Pair
                                {
                                    VertexBody = vertices.Body,
                                    TriangleBody = triangles.Body,
                                    Vertex = i,
                                    T0 = tris[t], T1 = tris[t + 1], T2 = tris[t + 2],
                                    Thickness = thickness,
                                    Friction = friction,
                                };
                            }
                        }
            }
        }

        /// <summary>One pass over the pairs after the bodies' substep of length <paramref name="h"/>.</summary>
        public void Solve(float h)
        {
            float invH = 1f / h;
            for (int k = 0; k < _count; k++)
            {
                ref Pair pair = ref _pairs[k];
                float pushed = pair.Pushed;
                pair.Pushed = 0f;
                SoftBody pb = pair.VertexBody, tb = pair.TriangleBody;
                int i = pair.Vertex, i0 = pair.T0, i1 = pair.T1, i2 = pair.T2;
                float wp = pb.W[i], w0 = tb.W[i0], w1 = tb.W[i1], w2 = tb.W[i2];
                if (wp + w0 + w1 + w2 == 0f) continue;
                Vector3 p = pb.X[i], x0 = tb.X[i0], x1 = tb.X[i1], x2 = tb.X[i2];
                Vector3 n = Vector3.Cross(x1 - x0, x2 - x0);
                float area2 = n.Length();
                if (area2 < 1e-12f) continue;
                n /= area2;
                float thickness = pair.Thickness;
                float before = Vector3.Dot(n, pb.XPrev[i] - tb.XPrev[i0]);
                if (tb.IsShell && before < 0f)
                {
                    n = -n;
                    before = -before;
                }
                float height = Vector3.Dot(n, p - x0);
                if (height >= thickness && !(pushed > 0f) || before < -thickness) continue;

                Vector3 closest = TriangleClosestPoint.Find(p, x0, x1, x2, out Vector3 b);
                // Face region only: beside the face the vertex belongs to a neighbouring face.
                if ((p - height * n - closest).LengthSquared() > 1e-10f) continue;
                float distance = height;
                Vector3 normal = n;
                float wSum = wp + b.X * b.X * w0 + b.Y * b.Y * w1 + b.Z * b.Z * w2;
                if (wSum <= 0f) continue;
                // A pair a Newton step already held apart has only friction left to do here.
                float dl = MathF.Max(0f, (thickness - distance) / wSum);
                if (dl > 0f)
                {
                    Move(pb, i, wp * dl * normal, invH);
                    Move(tb, i0, -w0 * b.X * dl * normal, invH);
                    Move(tb, i1, -w1 * b.Y * dl * normal, invH);
                    Move(tb, i2, -w2 * b.Z * dl * normal, invH);
                }

                Vector3 relative = (pb.X[i] - pb.XPrev[i])
                    - b.X * (tb.X[i0] - tb.XPrev[i0]) - b.Y * (tb.X[i1] - tb.XPrev[i1]) - b.Z * (tb.X[i2] - tb.XPrev[i2]);
                Vector3 tangent = relative - Vector3.Dot(relative, normal) * normal;
                float slip = tangent.Length();
                if (slip < 1e-9f) continue;
                float dlt = MathF.Min(slip / wSum, pair.Friction * (dl + pushed));
                Vector3 t = tangent / slip;
                Move(pb, i, -wp * dlt * t, invH);
                Move(tb, i0, w0 * b.X * dlt * t, invH);
                Move(tb, i1, w1 * b.Y * dlt * t, invH);
                Move(tb, i2, w2 * b.Z * dlt * t, invH);
            }
        }

        // A Newton body takes the correction as velocity only, carried out by its next implicit
        // step: moved here, the vertex alone strained the tets behind it (so did the push of
        // ImplicitNewtonSolver.PushSoftBodies into a Newton body that had already stepped): a
        // Newton box landing at 10 m/s on a Newton slab peaked at 3.2 kJ of strain at nu 0.49
        // (E 1e6 Pa) and 2.0 kJ at E 1e7 Pa for a 400 J motion, 0.47 and 0.26 kJ with velocity only.
        static void Move(SoftBody body, int vertex, Vector3 dx, float invH)
        {
            if (body.Solver != SoftSolver.Newton) body.X[vertex] += dx;
            body.V[vertex] += dx * invH;
        }
    }
}
