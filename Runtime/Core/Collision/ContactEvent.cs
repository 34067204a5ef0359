using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>What happened to a pair of shapes in the last step.</summary>
    public enum ContactEventKind : byte
    {
        /// <summary>The shapes started touching (or a sensor started overlapping).</summary>
        Begin = 0,
        /// <summary>The shapes were touching before and still are.</summary>
        Persist = 1,
        /// <summary>The shapes stopped touching (or one of them was removed).</summary>
        End = 2,
    }

    /// <summary>
    /// A contact or sensor event, written into a buffer that stays valid until the next step.
    /// Ordered deterministically (by shape pair). Impulses are the ones the solver applied.
    /// </summary>
    public struct ContactEvent
    {
        /// <summary>Begin, persist or end.</summary>
        public ContactEventKind Kind;
        /// <summary>True when one shape is a sensor: no physical response, no points.</summary>
        public bool IsSensor;
        /// <summary>First body.</summary>
        public BodyHandle BodyA;
        /// <summary>Second body.</summary>
        public BodyHandle BodyB;
        /// <summary>First shape.</summary>
        public ShapeHandle ShapeA;
        /// <summary>Second shape.</summary>
        public ShapeHandle ShapeB;
        /// <summary>World normal from A to B (zero for sensors and end events).</summary>
        public Vector3 Normal;
        /// <summary>Average contact point, world, metres.</summary>
        public Vector3 Point;
        /// <summary>Points in the manifold.</summary>
        public int PointCount;
        /// <summary>Sum of the normal impulses of the step, N s.</summary>
        public float NormalImpulse;
        /// <summary>Velocity of B relative to A at <see cref="Point"/> before the solve, m/s.</summary>
        public Vector3 RelativeVelocity;

        /// <summary>The same event with its handles issued by world <paramref name="worldId"/> (a restored state's pending events).</summary>
        internal readonly ContactEvent InWorld(int worldId)
        {
            ContactEvent e = this;
            e.BodyA = new BodyHandle(BodyA.Index, BodyA.Generation, worldId);
            e.BodyB = new BodyHandle(BodyB.Index, BodyB.Generation, worldId);
            e.ShapeA = new ShapeHandle(ShapeA.Index, ShapeA.Generation, worldId);
            e.ShapeB = new ShapeHandle(ShapeB.Index, ShapeB.Generation, worldId);
            return e;
        }
    }
}
