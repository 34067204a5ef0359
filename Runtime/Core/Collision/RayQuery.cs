using System.Numerics;

namespace Fulcrum.Collision
{
    /// <summary>
    /// Tree callback of the world's ray casts: tests each shape whose fat box the ray crosses.
    /// In closest mode it shortens the ray at every hit; in all mode it keeps the nearest
    /// <see cref="Capacity"/> hits in <see cref="Hits"/> (the world's reusable buffer), sorted by
    /// distance then shape slot, and counts every hit in <see cref="Found"/>.
    /// </summary>
    internal struct RayQuery : ITreeRayCallback
    {
        public World World;
        public QueryFilter Filter;
        public Vector3 Origin;
        public Vector3 Direction;   // unit
        public float Length;
        public bool All;
        public RayHit Best;
        public bool HasHit;
        public RayHit[] Hits;
        public int Capacity;
        public int Found;

        public float Visit(int proxyId, int shape, float maxFraction)
        {
            if (!World.PassesFilter(shape, Filter)) return maxFraction;
            ShapeStorage s = World.Shapes;
            if (!RayCaster.Cast(s.Geometry[shape], World.ShapeWorldPose(shape), Origin, Direction, maxFraction * Length, out float t, out Vector3 n))
                return maxFraction;
            var hit = new RayHit
            {
                Shape = new ShapeHandle(shape, s.Generation[shape], World.Id),
                Body = World.BodyHandleOf(s.Body[shape]),
                Point = Origin + Direction * t,
                Normal = n,
                Distance = t,
            };
            if (!All)
            {
                // Equal distances: the lower slot wins, whatever the tree order.
                if (!HasHit || NearestHits.Before(hit, Best)) Best = hit;
                HasHit = true;
                return t / Length;
            }
            NearestHits.Insert(Hits, Capacity, ref Found, hit);
            return maxFraction;
        }
    }
}
