using Fulcrum.Mathematics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Tree callback of continuous collision: for one shape of a sweeping body, lowers
    /// <see cref="Toi"/> to the time of impact against each shape in its swept bounds.
    /// </summary>
    internal struct CcdCandidates : ITreeOverlapCallback
    {
        public World World;
        public int Body;
        public int Shape;
        public BodySweep Sweep;
        public float Bound;
        public float TargetGap;
        public float Tolerance;
        public float FastApproach;
        public Aabb Swept;
        public float Toi;

        public bool Visit(int proxyId, int other)
        {
            float t = World.ShapeTimeOfImpact(Shape, other, Sweep, Bound, TargetGap, Tolerance, FastApproach, Toi, Swept);
            if (t < Toi) Toi = t;
            // Nothing comes before an impact at the very start.
            return Toi > 0;
        }
    }
}
