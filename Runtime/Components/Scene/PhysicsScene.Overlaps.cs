using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    public sealed partial class PhysicsScene
    {
        /// <summary>The colliders overlapping a sphere, in a new array (Unity's OverlapSphere; allocates).</summary>
        public Collider[] OverlapSphere(Vector3 position, float radius, int layerMask = DefaultRaycastLayers,
            QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            FieldCheck.Positive(radius, "PhysicsScene.OverlapSphere", nameof(radius));
            FieldCheck.Finite(position, "PhysicsScene.OverlapSphere", nameof(position));
            return OverlapAll(ShapeGeometry.Sphere(radius), new Pose(position, Quaternion.Identity), layerMask, queryTriggerInteraction, nameof(OverlapSphere));
        }

        /// <summary>
        /// The colliders overlapping a box (centre, half extents, orientation), written into
        /// <paramref name="results"/>; returns how many (Unity's OverlapBoxNonAlloc). Allocates nothing once warm.
        /// </summary>
        public int OverlapBox(Vector3 center, Vector3 halfExtents, Span<Collider> results, Quaternion orientation,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal) =>
            Overlap(BoxGeometry(halfExtents, "PhysicsScene.OverlapBox"), QueryPose(center, orientation, "PhysicsScene.OverlapBox"),
                results, layerMask, queryTriggerInteraction, nameof(OverlapBox));

        /// <summary>The colliders overlapping a box, in a new array (Unity's OverlapBox; allocates).</summary>
        public Collider[] OverlapBox(Vector3 center, Vector3 halfExtents, Quaternion orientation,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal) =>
            OverlapAll(BoxGeometry(halfExtents, "PhysicsScene.OverlapBox"), QueryPose(center, orientation, "PhysicsScene.OverlapBox"),
                layerMask, queryTriggerInteraction, nameof(OverlapBox));

        /// <summary>
        /// The colliders overlapping a capsule with hemisphere centres <paramref name="point0"/>
        /// and <paramref name="point1"/>, written into <paramref name="results"/> (Unity's
        /// OverlapCapsuleNonAlloc). Allocates nothing once warm.
        /// </summary>
        public int OverlapCapsule(Vector3 point0, Vector3 point1, float radius, Span<Collider> results,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            CapsuleGeometry(point0, point1, radius, "PhysicsScene.OverlapCapsule", out ShapeGeometry g, out Pose pose);
            return Overlap(g, pose, results, layerMask, queryTriggerInteraction, nameof(OverlapCapsule));
        }

        /// <summary>The colliders overlapping a capsule, in a new array (Unity's OverlapCapsule; allocates).</summary>
        public Collider[] OverlapCapsule(Vector3 point0, Vector3 point1, float radius,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            CapsuleGeometry(point0, point1, radius, "PhysicsScene.OverlapCapsule", out ShapeGeometry g, out Pose pose);
            return OverlapAll(g, pose, layerMask, queryTriggerInteraction, nameof(OverlapCapsule));
        }

        /// <summary>Whether any collider overlaps the sphere (Unity's CheckSphere). Allocates nothing.</summary>
        public bool CheckSphere(Vector3 position, float radius, int layerMask = DefaultRaycastLayers,
            QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            FieldCheck.Positive(radius, "PhysicsScene.CheckSphere", nameof(radius));
            FieldCheck.Finite(position, "PhysicsScene.CheckSphere", nameof(position));
            return Any(ShapeGeometry.Sphere(radius), new Pose(position, Quaternion.Identity), layerMask, queryTriggerInteraction, nameof(CheckSphere));
        }

        /// <summary>Whether any collider overlaps the box (Unity's CheckBox). Allocates nothing.</summary>
        public bool CheckBox(Vector3 center, Vector3 halfExtents, Quaternion orientation, int layerMask = DefaultRaycastLayers,
            QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal) =>
            Any(BoxGeometry(halfExtents, "PhysicsScene.CheckBox"), QueryPose(center, orientation, "PhysicsScene.CheckBox"),
                layerMask, queryTriggerInteraction, nameof(CheckBox));

        /// <summary>Whether any collider overlaps the capsule (Unity's CheckCapsule). Allocates nothing.</summary>
        public bool CheckCapsule(Vector3 start, Vector3 end, float radius, int layerMask = DefaultRaycastLayers,
            QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            CapsuleGeometry(start, end, radius, "PhysicsScene.CheckCapsule", out ShapeGeometry g, out Pose pose);
            return Any(g, pose, layerMask, queryTriggerInteraction, nameof(CheckCapsule));
        }

        /// <summary>
        /// The point of <paramref name="collider"/>, placed with its entity at
        /// <paramref name="position"/> and <paramref name="rotation"/> (not where it is),
        /// closest to <paramref name="point"/>; the point itself when inside (Unity's
        /// Physics.ClosestPoint). Box, sphere, capsule and convex mesh colliders; a non-convex
        /// MeshCollider throws.
        /// </summary>
        public Vector3 ClosestPoint(Vector3 point, Collider collider, Vector3 position, Quaternion rotation)
        {
            if (collider == null) throw new ArgumentNullException(nameof(collider));
            FieldCheck.Finite(point, "PhysicsScene.ClosestPoint", nameof(point));
            Pose pose = QueryPose(position, rotation, "PhysicsScene.ClosestPoint") * collider.LocalShapePose;
            return ShapeQueries.ClosestPoint(collider.BuildGeometry(), pose, point);
        }

        /// <summary>
        /// Whether two colliders, placed with their entities at the given poses (not where they
        /// are), overlap, and the shortest translation of <paramref name="colliderA"/> that
        /// separates them: <paramref name="direction"/> (unit) times <paramref name="distance"/>
        /// (Unity's Physics.ComputePenetration). Non-convex mesh colliders throw.
        /// </summary>
        public bool ComputePenetration(Collider colliderA, Vector3 positionA, Quaternion rotationA,
            Collider colliderB, Vector3 positionB, Quaternion rotationB, out Vector3 direction, out float distance)
        {
            if (colliderA == null) throw new ArgumentNullException(nameof(colliderA));
            if (colliderB == null) throw new ArgumentNullException(nameof(colliderB));
            Pose a = QueryPose(positionA, rotationA, "PhysicsScene.ComputePenetration") * colliderA.LocalShapePose;
            Pose b = QueryPose(positionB, rotationB, "PhysicsScene.ComputePenetration") * colliderB.LocalShapePose;
            return ShapeQueries.Penetration(colliderA.BuildGeometry(), a, colliderB.BuildGeometry(), b, out direction, out distance);
        }

        int Overlap(in ShapeGeometry g, in Pose pose, Span<Collider> results, int layerMask, QueryTriggerInteraction q, string query)
        {
            ThrowIfStepping(query);
            if (_overlapScratch.Length < results.Length) _overlapScratch = new ShapeHandle[Math.Max(results.Length, 2 * _overlapScratch.Length)];
            Span<ShapeHandle> shapes = new Span<ShapeHandle>(_overlapScratch, 0, results.Length);
            int found = Math.Min(_world.Overlap(g, pose, shapes, Filter(layerMask, q)), results.Length);
            int n = 0;
            for (int k = 0; k < found; k++)
            {
                Collider? c = GetCollider(shapes[k]);
                if (c != null) results[n++] = c;
            }
            return n;
        }

        Collider[] OverlapAll(in ShapeGeometry g, in Pose pose, int layerMask, QueryTriggerInteraction q, string query)
        {
            ThrowIfStepping(query);
            QueryFilter filter = Filter(layerMask, q);
            // One query into the scratch buffer; a second, larger one only when it overflowed.
            int count = _world.Overlap(g, pose, _overlapScratch, filter);
            if (count > _overlapScratch.Length)
            {
                _overlapScratch = new ShapeHandle[count];
                count = _world.Overlap(g, pose, _overlapScratch, filter);
            }
            var results = new Collider[count];
            int n = 0;
            for (int k = 0; k < count; k++)
            {
                Collider? c = GetCollider(_overlapScratch[k]);
                if (c != null) results[n++] = c;
            }
            if (n < count) Array.Resize(ref results, n);
            return results;
        }

        bool Any(in ShapeGeometry g, in Pose pose, int layerMask, QueryTriggerInteraction q, string query)
        {
            ThrowIfStepping(query);
            return _world.Overlap(g, pose, Span<ShapeHandle>.Empty, Filter(layerMask, q)) > 0;
        }
    }
}
