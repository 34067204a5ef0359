using Fulcrum.Collision;
using Fulcrum.Dynamics;

namespace Fulcrum
{
    public sealed partial class World
    {
        IslandBuilder _islands = new IslandBuilder();

        /// <summary>
        /// <see cref="StepStage.Islands"/>: wakes the sleeping islands that awake bodies touch
        /// through a listed manifold or a joint, lists the step's constraints (manifolds of
        /// awake pairs, unbroken joints of awake bodies) and groups them into islands by
        /// union-find. Reads: <see cref="Contacts"/> (the narrow phase's manifolds in pair
        /// order), the joints, the bodies' awake flags and types. Writes: the island builder's
        /// awake bodies, manifold and joint lists and islands (scratch of this step), the
        /// joint storage's per-body capacity, body awake flags and sleep timers of woken bodies.
        /// </summary>
        void Islands()
        {
            Joints.EnsureBodies(Bodies.SlotCount);
            _islands.Build(Bodies, Shapes, Contacts.Pool, Contacts.Source, Contacts.ManifoldCount, Joints);
        }

        /// <summary>Wakes the sleeping island of body <paramref name="slot"/>, if it sleeps in one.</summary>
        void WakeIsland(int slot) => _islands.WakeIsland(Bodies, slot);

        // A removed body may have held others up: wake everything that touches it (sleeping
        // neighbours included, through the persistent contacts), and take its joints with it.
        // Runs before its shapes, and so its contacts, are released.
        void OnBodyDestroyed(int slot)
        {
            WakeIsland(slot);
            ContactGraph g = ContactGraph;
            for (int s = Bodies.FirstShape[slot]; s >= 0; s = Shapes.NextInBody[s])
            {
                for (int e = g.FirstEdge(s); e >= 0; e = g.NextEdge(e))
                {
                    ref Contact c = ref g.Contacts[e >> 1];
                    if ((c.Flags & ContactFlags.Touching) == 0) continue;
                    Wake(c.BodyA == slot ? c.BodyB : c.BodyA);
                }
            }
            DestroyJointsOf(slot);
        }
    }
}
