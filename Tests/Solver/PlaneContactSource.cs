using System;
using System.Collections.Generic;
using System.Numerics;
using Fulcrum;
using Fulcrum.Collision;

namespace Fulcrum.Tests.Solver
{
    /// <summary>
    /// Test scaffolding standing in for the narrow phase: contact manifolds of boxes and spheres
    /// against one static half-space n.x &lt;= d, with speculative points within a margin and
    /// impulses carried by feature id, handed to the solver through World.TestNarrowPhase.
    /// </summary>
    sealed class PlaneContactSource
    {
        readonly BodyHandle _ground;
        readonly Vector3 _n;
        readonly float _d;
        readonly List<(BodyHandle body, ShapeGeometry shape, float friction, float restitution)> _bodies = new();
        public float Margin = 0.02f;
        public float RollingFriction { get; set; }

        public PlaneContactSource(World world, BodyHandle ground, Vector3 normal, float offset)
        {
            _ground = ground;
            _n = Vector3.Normalize(normal);
            _d = offset;
            world.TestNarrowPhase = Update;
        }

        public void Add(BodyHandle body, ShapeGeometry shape, float friction, float restitution = 0) =>
            _bodies.Add((body, shape, friction, restitution));

        void Update(World w)
        {
            if (w.TestManifolds.Length < _bodies.Count) Array.Resize(ref w.TestManifolds, _bodies.Count);
            int count = 0;
            int g = _ground.Index;
            Vector3 cA = w.Bodies.Center[g];
            Span<(float s, Vector3 p, uint id)> cand = stackalloc (float, Vector3, uint)[8];
            foreach (var (body, shape, friction, restitution) in _bodies)
            {
                int b = body.Index;
                ContactManifold old = FindOld(w, b);
                var m = new ContactManifold { BodyA = g, BodyB = b, ShapeA = 0, ShapeB = 0, Normal = _n, Friction = friction, Restitution = restitution, RollingFriction = RollingFriction };
                Vector3 cB = w.Bodies.Center[b];
                Quaternion q = w.Bodies.Rotation[b];
                Vector3 origin = w.Bodies.Position[b];
                int nc = 0;
                if (shape.Type == ShapeType.Sphere)
                {
                    Vector3 p = origin - shape.Radius * _n;
                    cand[nc++] = (Vector3.Dot(_n, p) - _d, p, 0);
                }
                else
                {
                    Vector3 h = shape.HalfExtents;
                    for (uint k = 0; k < 8; k++)
                    {
                        Vector3 local = new Vector3((k & 1) != 0 ? h.X : -h.X, (k & 2) != 0 ? h.Y : -h.Y, (k & 4) != 0 ? h.Z : -h.Z);
                        Vector3 p = origin + Vector3.Transform(local, q);
                        float s = Vector3.Dot(_n, p) - _d;
                        if (s < Margin) cand[nc++] = (s, p, k);
                    }
                    // Keep the four deepest.
                    for (int i = 0; i < nc; i++)
                        for (int j = i + 1; j < nc; j++)
                            if (cand[j].s < cand[i].s) (cand[i], cand[j]) = (cand[j], cand[i]);
                    nc = Math.Min(nc, 4);
                }
                for (int i = 0; i < nc; i++)
                {
                    if (cand[i].s >= Margin) continue;
                    ref ContactPoint cp = ref ContactManifold.Point(ref m, m.PointCount++);
                    Vector3 mid = cand[i].p - 0.5f * cand[i].s * _n;
                    cp.Position = mid;
                    cp.AnchorA = mid - cA;
                    cp.AnchorB = mid - cB;
                    cp.Separation = cand[i].s;
                    cp.FeatureId = cand[i].id;
                    for (int k = 0; k < old.PointCount; k++)
                    {
                        ContactPoint op = ContactManifold.Point(ref old, k);
                        if (op.FeatureId != cp.FeatureId) continue;
                        cp.NormalImpulse = op.NormalImpulse;
                        cp.TangentImpulse1 = op.TangentImpulse1;
                        cp.TangentImpulse2 = op.TangentImpulse2;
                        cp.Persisted = true;
                    }
                }
                if (m.PointCount == 0) continue;
                m.RollingImpulse = old.RollingImpulse;
                w.TestManifolds[count++] = m;
            }
            w.TestManifoldCount = count;
        }

        static ContactManifold FindOld(World w, int body)
        {
            for (int k = 0; k < w.TestManifoldCount; k++)
                if (w.TestManifolds[k].BodyB == body) return w.TestManifolds[k];
            return default;
        }
    }
}
