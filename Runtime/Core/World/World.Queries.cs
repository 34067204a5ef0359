using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum
{
    public sealed partial class World
    {
        // Set after each step: the step moved bodies after the broad phase sized their fat
        // boxes, so a query first brings the moving shapes' bounds up to date.
        bool _queryBoundsStale;
        readonly ContactBuffer _queryBuffer = new ContactBuffer();
        RayHit[] _rayHits = new RayHit[16];
        ShapeCastHit[] _castHits = new ShapeCastHit[16];
        int[] _overlaps = new int[16];

        /// <summary>
        /// The first shape along a ray, with the default filter (all layers, no sensors).
        /// See <see cref="RayCast(Vector3, Vector3, float, in QueryFilter, out RayHit)"/>.
        /// </summary>
        public bool RayCast(Vector3 origin, Vector3 direction, float maxDistance, out RayHit hit) =>
            RayCast(origin, direction, maxDistance, QueryFilter.Default, out hit);

        /// <summary>
        /// The first shape hit by the ray from <paramref name="origin"/> along
        /// <paramref name="direction"/> (any length, normalised here) within
        /// <paramref name="maxDistance"/> metres. Shapes the ray starts inside are not hit;
        /// meshes are hit from the front only. Ties go to the lower shape slot. Throws an
        /// <see cref="ArgumentException"/> for a zero or non-finite direction or origin, or a
        /// negative or NaN distance. Allocates nothing.
        /// </summary>
        public bool RayCast(Vector3 origin, Vector3 direction, float maxDistance, in QueryFilter filter, out RayHit hit)
        {
            Vector3 dir = CheckRay(origin, direction, ref maxDistance);
            var q = new RayQuery { World = this, Filter = filter, Origin = origin, Direction = dir, Length = maxDistance };
            CastRay(ref q);
            hit = q.Best;
            return q.HasHit;
        }

        /// <summary>
        /// Every shape the ray hits (see <see cref="RayCast(Vector3, Vector3, float, in QueryFilter, out RayHit)"/>),
        /// nearest first: the nearest <c>hits.Length</c> are written to <paramref name="hits"/>,
        /// and the return value counts all of them (more than the span holds means some were
        /// left out). Allocation-free once the world's scratch buffer has grown to the span's size.
        /// </summary>
        public int RayCastAll(Vector3 origin, Vector3 direction, float maxDistance, Span<RayHit> hits, in QueryFilter filter)
        {
            Vector3 dir = CheckRay(origin, direction, ref maxDistance);
            if (_rayHits.Length < hits.Length) _rayHits = new RayHit[Math.Max(hits.Length, 2 * _rayHits.Length)];
            var q = new RayQuery { World = this, Filter = filter, Origin = origin, Direction = dir, Length = maxDistance, All = true, Hits = _rayHits, Capacity = hits.Length };
            CastRay(ref q);
            new ReadOnlySpan<RayHit>(_rayHits, 0, Math.Min(q.Found, hits.Length)).CopyTo(hits);
            return q.Found;
        }

        /// <summary>Every shape the ray hits, with the default filter; see the overload taking a <see cref="QueryFilter"/>.</summary>
        public int RayCastAll(Vector3 origin, Vector3 direction, float maxDistance, Span<RayHit> hits) =>
            RayCastAll(origin, direction, maxDistance, hits, QueryFilter.Default);

        /// <summary>
        /// Sweeps a convex shape (sphere, box, capsule or hull) from <paramref name="pose"/>
        /// along <paramref name="direction"/> for up to <paramref name="maxDistance"/> metres
        /// and reports the first shape it touches. Shapes it touches at the start are not
        /// reported. Throws an <see cref="ArgumentException"/> for a plane or mesh, a bad pose,
        /// or a bad direction or distance. Allocates nothing.
        /// </summary>
        public bool ShapeCast(in ShapeGeometry shape, in Pose pose, Vector3 direction, float maxDistance, in QueryFilter filter, out ShapeCastHit hit)
        {
            var q = PrepareCast(shape, pose, direction, maxDistance, filter);
            CastShape(ref q);
            hit = q.Best;
            return q.HasHit;
        }

        /// <summary>The first shape a swept shape touches, with the default filter.</summary>
        public bool ShapeCast(in ShapeGeometry shape, in Pose pose, Vector3 direction, float maxDistance, out ShapeCastHit hit) =>
            ShapeCast(shape, pose, direction, maxDistance, QueryFilter.Default, out hit);

        /// <summary>
        /// Every shape a swept shape touches, nearest first, in the manner of
        /// <see cref="RayCastAll(Vector3, Vector3, float, Span{RayHit}, in QueryFilter)"/>.
        /// </summary>
        public int ShapeCastAll(in ShapeGeometry shape, in Pose pose, Vector3 direction, float maxDistance, Span<ShapeCastHit> hits, in QueryFilter filter)
        {
            var q = PrepareCast(shape, pose, direction, maxDistance, filter);
            if (_castHits.Length < hits.Length) _castHits = new ShapeCastHit[Math.Max(hits.Length, 2 * _castHits.Length)];
            q.All = true;
            q.Hits = _castHits;
            q.Capacity = hits.Length;
            CastShape(ref q);
            new ReadOnlySpan<ShapeCastHit>(_castHits, 0, Math.Min(q.Found, hits.Length)).CopyTo(hits);
            return q.Found;
        }

        /// <summary>
        /// The shapes overlapping (or touching) <paramref name="shape"/> at
        /// <paramref name="pose"/>, in slot order: the first <c>results.Length</c> are written
        /// and the return value counts all. Any shape kind may be used. Allocation-free once warm.
        /// </summary>
        public int Overlap(in ShapeGeometry shape, in Pose pose, Span<ShapeHandle> results, in QueryFilter filter)
        {
            CheckQueryShape(shape, pose, false);
            RefreshQueryBounds();
            Aabb box = shape.ComputeAabb(pose);
            var q = new OverlapQuery { World = this, Filter = filter, Shape = shape, Pose = pose, Buffer = _queryBuffer, Found = _overlaps };
            _broadPhase.StaticTree.Query(box, ref q);
            _broadPhase.MovingTree.Query(box, ref q);
            _overlaps = q.Found;
            Array.Sort(_overlaps, 0, q.Count);
            int n = Math.Min(q.Count, results.Length);
            for (int i = 0; i < n; i++) results[i] = new ShapeHandle(_overlaps[i], Shapes.Generation[_overlaps[i]], Id);
            return q.Count;
        }

        /// <summary>The shapes overlapping a shape at a pose, with the default filter.</summary>
        public int Overlap(in ShapeGeometry shape, in Pose pose, Span<ShapeHandle> results) =>
            Overlap(shape, pose, results, QueryFilter.Default);

        void CastRay(ref RayQuery q)
        {
            RefreshQueryBounds();
            Vector3 segment = q.Direction * q.Length;
            _broadPhase.StaticTree.RayCast(q.Origin, segment, 1f, ref q);
            float remaining = q.HasHit ? q.Best.Distance / q.Length : 1f;
            _broadPhase.MovingTree.RayCast(q.Origin, segment, remaining, ref q);
        }

        ShapeCastQuery PrepareCast(in ShapeGeometry shape, in Pose pose, Vector3 direction, float maxDistance, in QueryFilter filter)
        {
            CheckQueryShape(shape, pose, true);
            Vector3 dir = CheckRay(pose.Position, direction, ref maxDistance);
            var q = new ShapeCastQuery { World = this, Filter = filter, Cast = SupportShape.From(shape, pose), Direction = dir, Length = maxDistance };
            Aabb start = shape.ComputeAabb(pose);
            Vector3 motion = dir * maxDistance;
            q.SweptBounds = Aabb.Union(start, new Aabb(start.Min + motion, start.Max + motion));
            return q;
        }

        void CastShape(ref ShapeCastQuery q)
        {
            RefreshQueryBounds();
            _broadPhase.StaticTree.Query(q.SweptBounds, ref q);
            _broadPhase.MovingTree.Query(q.SweptBounds, ref q);
        }

        internal static Vector3 CheckRay(Vector3 origin, Vector3 direction, ref float maxDistance)
        {
            Validate.Finite(origin, "origin");
            float len = direction.Length();
            if (!(len > 1e-12f) || !float.IsFinite(len))
                throw new ArgumentException($"direction must be a finite, non-zero vector, got {direction}.", nameof(direction));
            if (!(maxDistance >= 0))
                throw new ArgumentException($"maxDistance must be >= 0, got {maxDistance}.", nameof(maxDistance));
            // An unbounded query still needs finite tree arithmetic.
            if (maxDistance > 1e7f) maxDistance = 1e7f;
            return direction / len;
        }

        internal static void CheckQueryShape(in ShapeGeometry shape, in Pose pose, bool convexOnly)
        {
            Validate.Finite(pose.Position, "pose.Position");
            Validate.Rotation(pose.Rotation, "pose.Rotation");
            if (shape.Type == ShapeType.ConvexHull && shape.Data == null || shape.Type == ShapeType.TriangleMesh && shape.Data == null ||
                shape.Type == ShapeType.Sphere && !(shape.Radius > 0))
                throw new ArgumentException("shape is unset or empty: build it with a ShapeGeometry factory.", nameof(shape));
            if (convexOnly && (shape.Type == ShapeType.Plane || shape.Type == ShapeType.TriangleMesh))
                throw new ArgumentException($"A shape cast needs a convex shape (sphere, box, capsule, hull), got {shape.Type}.", nameof(shape));
        }

        /// <summary>Whether a query with this filter sees the shape.</summary>
        internal bool PassesFilter(int shape, in QueryFilter filter)
        {
            ShapeStorage s = Shapes;
            if ((filter.LayerMask & (1u << s.Layer[shape])) == 0) return false;
            if (s.IsSensor[shape] && !filter.IncludeSensors) return false;
            if (!filter.IgnoreBody.IsNone && filter.IgnoreBody.Index == s.Body[shape] && filter.IgnoreBody.Generation == Bodies.Generation[s.Body[shape]]) return false;
            return true;
        }

        internal BodyHandle BodyHandleOf(int body) => new BodyHandle(body, Bodies.Generation[body], Id);

        // Recomputes the tight bounds of moving shapes at their current poses and moves the
        // proxies that left their fat boxes (they join the next step's pair search).
        internal void RefreshQueryBounds()
        {
            if (!_queryBoundsStale) return;
            _queryBoundsStale = false;
            ShapeStorage s = Shapes;
            for (int k = 0; k < s.ActiveCount; k++)
            {
                int i = s.Active[k];
                int body = s.Body[i];
                // Bodies that fell asleep in the step moved in it too: only static ones are skipped.
                if (Bodies.Type[body] == BodyType.Static) continue;
                Aabb tight = s.Geometry[i].ComputeAabb(ShapeWorldPose(i));
                s.WorldAabb[i] = tight;
                if (!_broadPhase.FatAabb(s.ProxyId[i]).Contains(tight))
                {
                    _broadPhase.MoveProxy(s.ProxyId[i], tight.Expanded(CollisionMargins.AabbMargin));
                    _fatBoxStep[i] = _stepIndex;
                }
            }
        }
    }
}
