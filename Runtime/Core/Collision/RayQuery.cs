using System;
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
                if (!HasHit || t < Best.Distance || (t == Best.Distance && shape < Best.Shape.Index)) Best = hit;
                HasHit = true;
                return t / Length;
            }
            // Insertion into the sorted prefix, dropping the farthest once full.
            int kept = Math.Min(Found, Capacity);
            Found++;
            int at = kept;
            while (at > 0 && Before(hit, Hits[at - 1])) at--;
            if (at >= Capacity) return maxFraction;
            for (int i = Math.Min(kept, Capacity - 1); i > at; i--) Hits[i] = Hits[i - 1];
            Hits[at] = hit;
            return maxFraction;
        }

        static bool Before(in RayHit a, in RayHit b) => a.Distance < b.Distance || (a.Distance == b.Distance && a.Shape.Index < b.Shape.Index);
    }
}
