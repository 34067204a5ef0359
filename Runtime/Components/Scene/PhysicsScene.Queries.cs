using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    public sealed partial class PhysicsScene
    {
        /// <summary>The layer queries skip by default, as in Unity ("Ignore Raycast").</summary>
        public const int IgnoreRaycastLayer = 2;

        /// <summary>Every layer but <see cref="IgnoreRaycastLayer"/> (Unity's Physics.DefaultRaycastLayers).</summary>
        public const int DefaultRaycastLayers = ~(1 << IgnoreRaycastLayer);

        /// <summary>Whether queries with <see cref="QueryTriggerInteraction.UseGlobal"/> see triggers. Default: true, as in Unity.</summary>
        public bool queriesHitTriggers { get; set; } = true;

        RayHit[] _rayScratch = new RayHit[16];
        ShapeHandle[] _overlapScratch = new ShapeHandle[16];

        /// <summary>
        /// The first collider along the ray from <paramref name="origin"/> in
        /// <paramref name="direction"/> (any length) within <paramref name="maxDistance"/>
        /// metres, on the layers of <paramref name="layerMask"/>. Colliders the ray starts inside
        /// are not hit (as in Unity); mesh colliders are hit from the front only. Allocates nothing.
        /// </summary>
        public bool Raycast(Vector3 origin, Vector3 direction, out RaycastHit hitInfo, float maxDistance = float.PositiveInfinity,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            ThrowIfStepping(nameof(Raycast));
            hitInfo = default;
            if (!_world.RayCast(origin, direction, maxDistance, Filter(layerMask, queryTriggerInteraction), out RayHit hit)) return false;
            return ToHit(hit.Shape, hit.Point, hit.Normal, hit.Distance, out hitInfo);
        }

        /// <summary>
        /// Every collider along the ray, nearest first, written into <paramref name="results"/>;
        /// returns how many were written (Unity's RaycastNonAlloc). Allocates nothing once warm.
        /// </summary>
        public int RaycastNonAlloc(Vector3 origin, Vector3 direction, Span<RaycastHit> results, float maxDistance = float.PositiveInfinity,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            ThrowIfStepping(nameof(RaycastNonAlloc));
            if (_rayScratch.Length < results.Length) _rayScratch = new RayHit[Math.Max(results.Length, 2 * _rayScratch.Length)];
            Span<RayHit> hits = new Span<RayHit>(_rayScratch, 0, results.Length);
            int found = Math.Min(_world.RayCastAll(origin, direction, maxDistance, hits, Filter(layerMask, queryTriggerInteraction)), results.Length);
            int n = 0;
            for (int k = 0; k < found; k++)
                if (ToHit(hits[k].Shape, hits[k].Point, hits[k].Normal, hits[k].Distance, out RaycastHit h)) results[n++] = h;
            return n;
        }

        /// <summary>
        /// Sweeps a sphere of <paramref name="radius"/> from <paramref name="origin"/> along
        /// <paramref name="direction"/>; the first collider it touches within
        /// <paramref name="maxDistance"/> (Unity's SphereCast; <see cref="RaycastHit.distance"/> is
        /// how far the centre travelled). Colliders overlapping the start are not reported.
        /// </summary>
        public bool SphereCast(Vector3 origin, float radius, Vector3 direction, out RaycastHit hitInfo, float maxDistance = float.PositiveInfinity,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            FieldCheck.Positive(radius, "PhysicsScene.SphereCast", nameof(radius));
            FieldCheck.Finite(origin, "PhysicsScene.SphereCast", nameof(origin));
            ThrowIfStepping(nameof(SphereCast));
            hitInfo = default;
            if (!_world.ShapeCast(ShapeGeometry.Sphere(radius), new Pose(origin, Quaternion.Identity), direction, maxDistance,
                    Filter(layerMask, queryTriggerInteraction), out ShapeCastHit hit)) return false;
            return ToHit(hit.Shape, hit.Point, hit.Normal, hit.Distance, out hitInfo);
        }

        /// <summary>
        /// The colliders overlapping a sphere, written into <paramref name="results"/>; returns how
        /// many were written (Unity's OverlapSphereNonAlloc). Allocates nothing once warm.
        /// </summary>
        public int OverlapSphere(Vector3 position, float radius, Span<Collider> results,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            FieldCheck.Positive(radius, "PhysicsScene.OverlapSphere", nameof(radius));
            FieldCheck.Finite(position, "PhysicsScene.OverlapSphere", nameof(position));
            ThrowIfStepping(nameof(OverlapSphere));
            if (_overlapScratch.Length < results.Length) _overlapScratch = new ShapeHandle[Math.Max(results.Length, 2 * _overlapScratch.Length)];
            Span<ShapeHandle> shapes = new Span<ShapeHandle>(_overlapScratch, 0, results.Length);
            int found = Math.Min(_world.Overlap(ShapeGeometry.Sphere(radius), new Pose(position, Quaternion.Identity), shapes,
                Filter(layerMask, queryTriggerInteraction)), results.Length);
            int n = 0;
            for (int k = 0; k < found; k++)
            {
                Collider? c = GetCollider(shapes[k]);
                if (c != null) results[n++] = c;
            }
            return n;
        }

        internal QueryFilter Filter(int layerMask, QueryTriggerInteraction q)
        {
            QueryFilter f = QueryFilter.Layers(unchecked((uint)layerMask));
            f.IncludeSensors = q == QueryTriggerInteraction.Collide || (q == QueryTriggerInteraction.UseGlobal && queriesHitTriggers);
            return f;
        }

        internal bool ToHit(ShapeHandle shape, Vector3 point, Vector3 normal, float distance, out RaycastHit hit)
        {
            Collider? c = GetCollider(shape);
            hit = c == null ? default : new RaycastHit { point = point, normal = normal, distance = distance, collider = c };
            return c != null;
        }

        void ThrowIfStepping(string query)
        {
            if (_world.IsStepping) throw new InvalidOperationException($"PhysicsScene.{query} cannot run while the world steps (from a callback inside World.Step).");
        }
    }
}
