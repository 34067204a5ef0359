using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    internal sealed partial class NarrowPhase
    {
        // Rewrites a contact's manifold chain from the buffer; points whose feature id
        // existed last step inherit its accumulated impulses (warm starting).
        void WriteManifolds(ref Contact ct, ContactBuffer buffer)
        {
            ContactGraph g = Graph;
            ContactPointCache cache = _pointCache;
            cache.Capture(g, ct.FirstManifold);

            // Resize the chain to the number of patches.
            int patches = Math.Min(buffer.PatchCount, ContactGraph.MaxManifoldsPerPair);
            int first = ct.FirstManifold;
            if (patches == 0) { g.FreeManifolds(ref ct); return; }
            if (first < 0) first = ct.FirstManifold = g.AllocateManifold();
            int m = first;
            for (int p = 1; p < patches; p++)
            {
                if (g.ManifoldNext[m] < 0)
                {
                    // Allocate first: the pool may grow, and the link must go into the new array.
                    int next = g.AllocateManifold();
                    g.ManifoldNext[m] = next;
                }
                m = g.ManifoldNext[m];
            }
            if (g.ManifoldNext[m] >= 0)
            {
                var tail = new Contact { FirstManifold = g.ManifoldNext[m] };
                g.FreeManifolds(ref tail);
                g.ManifoldNext[m] = -1;
            }
            ct.ManifoldCount = patches;

            ShapeStorage s = _in.Shapes;
            int sa = ct.ShapeA, sb = ct.ShapeB;
            float friction = Combine.Values(s.Friction[sa], s.FrictionCombine[sa], s.Friction[sb], s.FrictionCombine[sb]);
            float restitution = Combine.Values(s.Restitution[sa], s.RestitutionCombine[sa], s.Restitution[sb], s.RestitutionCombine[sb]);
            Vector3 centerA = _in.Bodies.Center[ct.BodyA], centerB = _in.Bodies.Center[ct.BodyB];
            Vector3 sum = Vector3.Zero;
            int total = 0;
            m = first;
            for (int p = 0; p < patches; p++, m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                int start = buffer.PatchStart[p], count = buffer.PatchPointCount(p);
                mf.BodyA = ct.BodyA;
                mf.BodyB = ct.BodyB;
                mf.ShapeA = sa;
                mf.ShapeB = sb;
                mf.Normal = buffer.PatchNormal[p];
                mf.PointCount = count;
                mf.Friction = friction;
                mf.Restitution = restitution;
                mf.RollingFriction = 0;
                mf.RollingImpulse = cache.RollingImpulse(p);
                for (int i = 0; i < count; i++)
                {
                    ref ContactPoint cp = ref ContactManifold.Point(ref mf, i);
                    Vector3 x = buffer.Position[start + i];
                    cp.Position = x;
                    cp.AnchorA = x - centerA;
                    cp.AnchorB = x - centerB;
                    cp.Separation = buffer.Separation[start + i];
                    cp.FeatureId = buffer.Id[start + i];
                    cp.RelativeNormalVelocity = 0;
                    cp.AppliedImpulse = 0; // the solver sets it if it runs this step
                    cp.Persisted = cache.TryTake(cp.FeatureId, out cp.NormalImpulse, out cp.TangentImpulse1, out cp.TangentImpulse2);
                    sum += x;
                    total++;
                }
            }
            if (total > 0)
            {
                Vector3 at = sum / total;
                ct.RelativeVelocity = PointVelocity(ct.BodyB, at) - PointVelocity(ct.BodyA, at);
            }
        }

        Vector3 PointVelocity(int body, Vector3 at) =>
            _in.Bodies.LinearVelocity[body] + Vector3.Cross(_in.Bodies.AngularVelocity[body], at - _in.Bodies.Center[body]);

        // A contact with manifolds this step, to be listed for the solver (each contact is
        // updated at most once per step, so at most once here).
        void AddToSort(ulong key, int contact)
        {
            if (_sortCount == _sortKeys.Length)
            {
                Array.Resize(ref _sortKeys, 2 * _sortCount);
                Array.Resize(ref _sortItems, 2 * _sortCount);
            }
            _sortKeys[_sortCount] = key;
            _sortItems[_sortCount] = contact;
            _sortCount++;
        }

        // Counts the touching points and the deepest penetration of a contact listed this step.
        void Measure(in Contact ct)
        {
            ContactGraph g = Graph;
            float slop = _in.LinearSlop;
            for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                for (int i = 0; i < mf.PointCount; i++)
                {
                    float sep = ContactManifold.Point(ref mf, i).Separation;
                    if (sep <= slop) Touching++;
                    if (-sep > MaxPenetration) MaxPenetration = -sep;
                }
            }
        }

        // Lists the manifolds of this step's updated, non-sensor contacts for the solver,
        // ordered by shape pair.
        void GatherManifolds()
        {
            ContactGraph g = Graph;
            int n = _sortCount;
            _contactOrder.Sort(_sortKeys, _sortItems, n);
            for (int k = 0; k < n; k++)
            {
                ref Contact ct = ref g.Contacts[_sortItems[k]];
                for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
                    Contacts.Add(m);
            }
            Contacts.Pool = g.Manifolds;
        }
    }
}
