using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// What one narrow phase reads from the rest of the world, handed to
    /// <see cref="NarrowPhase.Run{THost}"/> by the world's stage method: the storages, the
    /// broad phase's fat boxes and this step's per-shape data, and the settings it uses.
    /// A value passed once per step (the storages are replaced when a state is restored, and
    /// the per-shape arrays grow with the shape slots, so the narrow phase keeps no copy).
    /// </summary>
    internal struct NarrowPhaseInput
    {
        /// <summary>Body poses, velocities, centres, types and awake flags.</summary>
        public BodyStorage Bodies;
        /// <summary>Shape geometry, bounds, proxies, materials and owners.</summary>
        public ShapeStorage Shapes;
        /// <summary>The proxies' fat boxes (pairs whose fat boxes parted end here).</summary>
        public BroadPhase BroadPhase;
        /// <summary>Per shape slot: how far the shape can move in this step (the broad phase's).</summary>
        public float[] ShapeMotion;
        /// <summary>Per shape slot: the farthest its geometry reaches from its own origin.</summary>
        public float[] ShapeRadius;
        /// <summary>Per shape slot: this step's world pose, valid where <see cref="ShapePoseStep"/> is <see cref="StepIndex"/>.</summary>
        public Pose[] ShapePose;
        /// <summary>Per shape slot: the step <see cref="ShapePose"/> was computed in.</summary>
        public long[] ShapePoseStep;
        /// <summary>Per shape slot: the step its fat box last changed.</summary>
        public long[] FatBoxStep;
        /// <summary>The index of this step.</summary>
        public long StepIndex;
        /// <summary>The step's time step, seconds.</summary>
        public float Dt;
        /// <summary>The speculative distance every pair keeps (<see cref="CollisionMargins.SpeculativeDistance"/>).</summary>
        public float SpeculativeBase;
        /// <summary><see cref="WorldSettings.LinearSlop"/>: points closer than this count as touching.</summary>
        public float LinearSlop;
        /// <summary><see cref="WorldSettings.ManifoldReuseDistance"/>.</summary>
        public float ReuseDistance;
        /// <summary><see cref="WorldSettings.ManifoldReuseAngle"/>.</summary>
        public float ReuseAngle;
        /// <summary><see cref="WorldSettings.Threads"/>: more than one runs the pair functions in parallel when there are enough.</summary>
        public int Threads;
    }
}
