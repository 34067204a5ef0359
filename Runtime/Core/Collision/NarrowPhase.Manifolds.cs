using System;
using System.Numerics;

namespace Fulcrum.Collision
{
    internal sealed partial class NarrowPhase
    {
        // Gives a contact's manifold chain one manifold per patch of the buffer (serial: the
        // graph's free list is shared).
        void ResizeChain(ref Contact ct, ContactBuffer buffer)
        {
            ContactGraph g = Graph;
            int patches = Math.Min(buffer.PatchCount, ContactGraph.MaxManifoldsPerPair);
            if (patches == ct.ManifoldCount) return;
            if (patches == 0) { g.FreeManifolds(ref ct); return; }
            int m = ct.FirstManifold;
            if (m < 0) m = ct.FirstManifold = g.AllocateManifold();
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
        }

        // Rewrites the points of a contact's manifold chain (already one manifold per patch,
        // ResizeChain) from the buffer; points whose feature id is in the cache (last step's
        // points, captured before the chain was resized) inherit its accumulated impulses (warm
        // starting). Writes only this contact and its manifolds (the parallel pass runs it with
        // a cache of its own).
        void WriteManifolds(ref Contact ct, ContactBuffer buffer, ContactPointCache cache)
        {
            ContactGraph g = Graph;
            int patches = ct.ManifoldCount;
            if (patches == 0) return;
            int first = ct.FirstManifold;
            int m;

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

        // The touching points and the deepest penetration of a contact listed this step.
        void Measure(in Contact ct, out int touching, out float deepest)
        {
            ContactGraph g = Graph;
            float slop = _in.LinearSlop;
            touching = 0;
            deepest = 0;
            for (int m = ct.FirstManifold; m >= 0; m = g.ManifoldNext[m])
            {
                ref ContactManifold mf = ref g.Manifolds[m];
                for (int i = 0; i < mf.PointCount; i++)
                {
                    float sep = ContactManifold.Point(ref mf, i).Separation;
                    if (sep <= slop) touching++;
                    if (-sep > deepest) deepest = -sep;
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
