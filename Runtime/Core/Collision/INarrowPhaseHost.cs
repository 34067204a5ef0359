namespace Fulcrum.Collision
{
    /// <summary>
    /// What the narrow phase asks of its world while it runs. A struct implementing this is
    /// passed by reference as a generic argument, so the calls are direct and allocate nothing.
    /// </summary>
    internal interface INarrowPhaseHost
    {
        /// <summary>Wakes sleeping dynamic body <paramref name="body"/> (and its island): a new manifold touches it.</summary>
        void Wake(int body);

        /// <summary>Touching contact <paramref name="contact"/> is about to be destroyed (its fat boxes parted): record its End event.</summary>
        void ContactEnded(int contact);

        /// <summary>The scheduler to run the pair functions on (called only when <see cref="NarrowPhaseInput.Threads"/> &gt; 1).</summary>
        IParallelScheduler? Workers();
    }
}
