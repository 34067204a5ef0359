using System;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The contact manifolds of the current step, for the solver: [0, <see cref="ManifoldCount"/>)
    /// in a deterministic order (by shape pair, then by manifold within a mesh pair), each an
    /// index (<see cref="Source"/>) into the contact graph's manifold pool (<see cref="Pool"/>).
    /// Each holds only non-sensor pairs with at least one awake dynamic body and at least one
    /// point (speculative points included).
    /// <para>
    /// Written by <see cref="NarrowPhase"/>, which owns it. The solver reads the geometry and
    /// writes the accumulated impulses (<see cref="ContactPoint.NormalImpulse"/>,
    /// <see cref="ContactPoint.TangentImpulse1"/>, <see cref="ContactPoint.TangentImpulse2"/>,
    /// <see cref="ContactManifold.RollingImpulse"/>) and
    /// <see cref="ContactPoint.RelativeNormalVelocity"/> in place, in the pool itself, where the
    /// next step's narrow phase hands them to the points with the same feature id
    /// (<see cref="ContactPoint.Persisted"/> = true) for warm starting. Nothing is copied: an
    /// earlier version copied every manifold (~330 bytes) out and the impulses back each step.
    /// </para>
    /// </summary>
    internal sealed class ContactSet
    {
        /// <summary>The manifold pool the indices refer to (as of the last narrow phase; the pool may be reallocated only there).</summary>
        internal ContactManifold[] Pool = Array.Empty<ContactManifold>();
        /// <summary>How many manifolds this step has.</summary>
        internal int ManifoldCount;
        /// <summary>For each of this step's manifolds, its slot in <see cref="Pool"/>.</summary>
        internal int[] Source = new int[16];

        internal void Clear() => ManifoldCount = 0;

        /// <summary>Manifold <paramref name="k"/> of this step, in the pool.</summary>
        internal ref ContactManifold this[int k] => ref Pool[Source[k]];

        /// <summary>Sizes the list for <paramref name="manifolds"/> manifolds.</summary>
        internal void Reserve(int manifolds)
        {
            if (Source.Length < manifolds) Array.Resize(ref Source, manifolds);
        }

        /// <summary>Appends pooled manifold <paramref name="source"/>.</summary>
        internal void Add(int source)
        {
            if (ManifoldCount == Source.Length) Array.Resize(ref Source, 2 * Source.Length);
            Source[ManifoldCount++] = source;
        }
    }
}
