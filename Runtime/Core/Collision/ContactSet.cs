using System;

namespace Fulcrum.Collision
{
    /// <summary>
    /// The contact manifolds of the current step, for the solver: <see cref="Manifolds"/>
    /// [0, <see cref="ManifoldCount"/>) in a deterministic order (by shape pair, then by
    /// manifold within a mesh pair). Each holds only non-sensor pairs with at least one
    /// awake dynamic body and at least one point (speculative points included).
    /// <para>
    /// Written by <c>World.UpdateContacts</c> (narrow phase). The solver reads the geometry and
    /// writes the accumulated impulses (<see cref="ContactPoint.NormalImpulse"/>,
    /// <see cref="ContactPoint.TangentImpulse1"/>, <see cref="ContactPoint.TangentImpulse2"/>,
    /// <see cref="ContactManifold.RollingImpulse"/>) and
    /// <see cref="ContactPoint.RelativeNormalVelocity"/> in place; <c>World.PublishEvents</c>
    /// copies them back to the persistent contacts, which hand them to next step's points with
    /// the same feature id (<see cref="ContactPoint.Persisted"/> = true) for warm starting.
    /// </para>
    /// </summary>
    internal sealed class ContactSet
    {
        /// <summary>This step's manifolds; only [0, ManifoldCount) are meaningful.</summary>
        internal ContactManifold[] Manifolds = new ContactManifold[16];
        /// <summary>How many manifolds this step has.</summary>
        internal int ManifoldCount;
        /// <summary>For each manifold, its slot in the contact graph's manifold pool (for the copy back).</summary>
        internal int[] Source = new int[16];

        internal void Clear() => ManifoldCount = 0;

        /// <summary>Appends a copy of a pooled manifold.</summary>
        internal void Add(in ContactManifold manifold, int source)
        {
            if (ManifoldCount == Manifolds.Length)
            {
                Array.Resize(ref Manifolds, 2 * Manifolds.Length);
                Array.Resize(ref Source, 2 * Source.Length);
            }
            Manifolds[ManifoldCount] = manifold;
            Source[ManifoldCount] = source;
            ManifoldCount++;
        }

        /// <summary>The manifolds as a span (for tests and tools).</summary>
        internal ReadOnlySpan<ContactManifold> AsSpan() => new ReadOnlySpan<ContactManifold>(Manifolds, 0, ManifoldCount);
    }
}
