using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.SoftBodies
{
    /// <summary>
    /// Vertex-versus-static-triangle-mesh contacts of one soft body. Once per step each vertex's
    /// path over the step (x to x + v dt, padded by the collision radius, a gravity term and
    /// half the travel again) is boxed in the mesh frame and the mesh's BVH gives the triangles
    /// it may meet; each pair keeps the triangle in world space (meshes are static). Each
    /// iteration then pushes the vertex out to the collision radius from the closest point of
    /// each of its triangles, with Coulomb friction, like the other shapes.
    /// One-sided like the rigid mesh collider: a triangle acts only on a vertex that was in
    /// front of its plane (or less than the collision radius behind it) at the start of the
    /// substep, so a vertex coming from the back side passes through; a vertex behind the
    /// plane is pushed out along the triangle normal only while its projection falls on the
    /// triangle (beside it, it is the neighbouring triangle's business).
    /// </summary>
    internal sealed class MeshVertexContacts
    {
        struct Pair
        {
            public int Vertex;
            public Vector3 A, B, C, Normal;
            public float Friction;
        }

        struct TriangleVisitor : ITreeOverlapCallback
        {
            public MeshVertexContacts Owner;
            public TriangleMesh Mesh;
            public Pose Pose;
            public Aabb Box;
            public Vector3 Start;
            public float Radius;
            public int Vertex;
            public float Friction;

            public bool Visit(int proxyId, int triangle)
            {
                if (!Mesh.TriangleOverlaps(Box, triangle, out Vector3 a, out Vector3 b, out Vector3 c)) return true;
                Vector3 n = Mesh.Normals[triangle];
                // Already behind the one-sided triangle when the step starts: the back side.
                if (Vector3.Dot(n, Start - a) < -Radius) return true;
                Owner.Add(new Pair
                {
                    Vertex = Vertex,
                    A = Pose.TransformPoint(a),
                    B = Pose.TransformPoint(b),
                    C = Pose.TransformPoint(c),
                    Normal = Pose.TransformDirection(n),
                    Friction = Friction,
                });
                return true;
            }
        }

        Pair[] _pairs = Array.Empty<Pair>();
        int _count;

        /// <summary>Vertex-triangle pairs gathered for this step.</summary>
        public int Count => _count;

        /// <summary>Forgets last step's pairs.</summary>
        public void Clear() => _count = 0;

        /// <summary>Adds the pairs of every free vertex of <paramref name="body"/> with the triangles of mesh shape <paramref name="shape"/> its path over <paramref name="dt"/> may meet.</summary>
        public void Gather(World world, int shape, SoftBody body, float dt, float gravity)
        {
            ShapeStorage s = world.Shapes;
            var visitor = new TriangleVisitor
            {
                Owner = this,
                Mesh = (TriangleMesh)s.Geometry[shape].Data!,
                Pose = world.ShapeWorldPose(shape),
                Radius = body.CollisionRadius,
                Friction = Combine.Values(body.Friction, s.FrictionCombine[shape], s.Friction[shape], s.FrictionCombine[shape]),
            };
            Aabb meshBox = s.WorldAabb[shape];
            Vector3[] x = body.X, v = body.V;
            float[] free = body.FreeW;
            float basePad = body.CollisionRadius + gravity * dt * dt + 0.002f;
            for (int i = 0; i < x.Length; i++)
            {
                if (free[i] == 0f) continue; // pinned or attached: see ShapeContactSolver.Solve
                Vector3 end = x[i] + v[i] * dt;
                float pad = basePad + 0.5f * v[i].Length() * dt;
                var path = new Aabb(Vector3.Min(x[i], end), Vector3.Max(x[i], end)).Expanded(pad);
                if (!path.Overlaps(meshBox)) continue;
                Vector3 start = visitor.Pose.InverseTransformPoint(x[i]);
                Vector3 localEnd = visitor.Pose.InverseTransformPoint(end);
                visitor.Box = new Aabb(Vector3.Min(start, localEnd), Vector3.Max(start, localEnd)).Expanded(pad);
                visitor.Start = start;
                visitor.Vertex = i;
                visitor.Mesh.Bvh.Query(visitor.Box, ref visitor);
            }
        }

        void Add(in Pair pair)
        {
            if (_count == _pairs.Length) Array.Resize(ref _pairs, Math.Max(16, 2 * _count));
            _pairs[_count++] = pair;
        }

        /// <summary>
        /// One pass over the pairs (zero compliance; the mesh is static, so the vertex takes the
        /// whole correction), then friction as in <see cref="ShapeContactSolver.Solve"/>, against
        /// the substep's normal corrections <paramref name="pushed"/> less <paramref name="held"/>.
        /// </summary>
        public void Solve(SoftBody body, float[] pushed, float[] held)
        {
            Vector3[] x = body.X, xPrev = body.XPrev;
            float[] w = body.W;
            float radius = body.CollisionRadius;
            for (int k = 0; k < _count; k++)
            {
                ref readonly Pair pair = ref _pairs[k];
                int i = pair.Vertex;
                if (w[i] == 0f) continue;
                Vector3 p = x[i];
                float height = Vector3.Dot(pair.Normal, p - pair.A);
                if (height >= radius) continue;
                if (Vector3.Dot(pair.Normal, xPrev[i] - pair.A) < -radius) continue;
                Vector3 closest = TriangleClosestPoint.Find(p, pair.A, pair.B, pair.C, out _);
                float distance;
                Vector3 n;
                if (height >= 0f)
                {
                    Vector3 d = p - closest;
                    distance = d.Length();
                    if (distance >= radius) continue;
                    n = distance > 1e-9f ? d / distance : pair.Normal;
                }
                else
                {
                    // Behind the plane: only straight under the face.
                    if ((p - height * pair.Normal - closest).LengthSquared() > 1e-10f) continue;
                    distance = height;
                    n = pair.Normal;
                }
                float push = radius - distance;
                x[i] += push * n;
                pushed[i] += push / w[i];

                Vector3 relative = x[i] - xPrev[i];
                Vector3 tangent = relative - Vector3.Dot(relative, n) * n;
                float slip = tangent.Length();
                if (slip < 1e-9f) continue;
                // Static friction holds the whole slip; beyond the cone the correction is capped.
                float cone = MathF.Max(0f, pair.Friction * pushed[i] - held[i]) * w[i];
                float take = MathF.Min(slip, cone);
                held[i] += take / w[i];
                x[i] -= tangent * (take / slip);
            }
        }
    }
}
