using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    public sealed partial class PhysicsScene
    {
        /// <summary>The first collider along <paramref name="ray"/>; see <see cref="Raycast(Vector3, Vector3, out RaycastHit, float, int, QueryTriggerInteraction)"/>.</summary>
        public bool Raycast(Ray ray, out RaycastHit hitInfo, float maxDistance = float.PositiveInfinity,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal) =>
            Raycast(ray.origin, ray.direction, out hitInfo, maxDistance, layerMask, queryTriggerInteraction);

        /// <summary>
        /// Every collider along the ray, nearest first, in a new array (Unity's RaycastAll; it
        /// allocates: use <see cref="RaycastNonAlloc"/> in a game loop).
        /// </summary>
        public RaycastHit[] RaycastAll(Vector3 origin, Vector3 direction, float maxDistance = float.PositiveInfinity,
            int layerMask = DefaultRaycastLayers, QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            ThrowIfStepping(nameof(RaycastAll));
            QueryFilter filter = Filter(layerMask, queryTriggerInteraction);
            // One cast into the scratch buffer; a second, larger one only when it overflowed.
            int count = _world.RayCastAll(origin, direction, maxDistance, _rayScratch, filter);
            if (count > _rayScratch.Length)
            {
                _rayScratch = new RayHit[count];
                count = _world.RayCastAll(origin, direction, maxDistance, _rayScratch, filter);
            }
            var results = new RaycastHit[count];
            int n = 0;
            for (int k = 0; k < count; k++)
                if (ToHit(_rayScratch[k].Shape, _rayScratch[k].Point, _rayScratch[k].Normal, _rayScratch[k].Distance, out RaycastHit h)) results[n++] = h;
            if (n < count) Array.Resize(ref results, n);
            return results;
        }

        /// <summary>
        /// Sweeps a box (centre, half extents, <paramref name="orientation"/>) along
        /// <paramref name="direction"/>: the first collider it touches within
        /// <paramref name="maxDistance"/> (Unity's BoxCast; distance is how far the centre
        /// travelled). Colliders overlapping the start are not reported.
        /// </summary>
        public bool BoxCast(Vector3 center, Vector3 halfExtents, Vector3 direction, out RaycastHit hitInfo, Quaternion orientation,
            float maxDistance = float.PositiveInfinity, int layerMask = DefaultRaycastLayers,
            QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            ShapeGeometry g = BoxGeometry(halfExtents, "PhysicsScene.BoxCast");
            Pose pose = QueryPose(center, orientation, "PhysicsScene.BoxCast");
            return Cast(g, pose, direction, out hitInfo, maxDistance, layerMask, queryTriggerInteraction, nameof(BoxCast));
        }

        /// <summary><see cref="BoxCast(Vector3, Vector3, Vector3, out RaycastHit, Quaternion, float, int, QueryTriggerInteraction)"/> with the box unrotated.</summary>
        public bool BoxCast(Vector3 center, Vector3 halfExtents, Vector3 direction, out RaycastHit hitInfo) =>
            BoxCast(center, halfExtents, direction, out hitInfo, Quaternion.Identity);

        /// <summary>
        /// Sweeps a capsule whose hemisphere centres are <paramref name="point1"/> and
        /// <paramref name="point2"/> (Unity's CapsuleCast); see <see cref="SphereCast"/>.
        /// </summary>
        public bool CapsuleCast(Vector3 point1, Vector3 point2, float radius, Vector3 direction, out RaycastHit hitInfo,
            float maxDistance = float.PositiveInfinity, int layerMask = DefaultRaycastLayers,
            QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            CapsuleGeometry(point1, point2, radius, "PhysicsScene.CapsuleCast", out ShapeGeometry g, out Pose pose);
            return Cast(g, pose, direction, out hitInfo, maxDistance, layerMask, queryTriggerInteraction, nameof(CapsuleCast));
        }

        bool Cast(in ShapeGeometry g, in Pose pose, Vector3 direction, out RaycastHit hitInfo, float maxDistance, int layerMask,
            QueryTriggerInteraction q, string query)
        {
            ThrowIfStepping(query);
            hitInfo = default;
            if (!_world.ShapeCast(g, pose, direction, maxDistance, Filter(layerMask, q), out ShapeCastHit hit)) return false;
            return ToHit(hit.Shape, hit.Point, hit.Normal, hit.Distance, out hitInfo);
        }

        static ShapeGeometry BoxGeometry(Vector3 halfExtents, string owner)
        {
            FieldCheck.Size(halfExtents.X, owner, "halfExtents.x");
            FieldCheck.Size(halfExtents.Y, owner, "halfExtents.y");
            FieldCheck.Size(halfExtents.Z, owner, "halfExtents.z");
            return ShapeGeometry.Box(halfExtents);
        }

        static Pose QueryPose(Vector3 position, Quaternion rotation, string owner)
        {
            FieldCheck.Position(position, owner, "position");
            return new Pose(position, FieldCheck.Rotation(rotation, owner, "orientation"));
        }

        // A capsule between two hemisphere centres: Fulcrum's capsules run along local y.
        static void CapsuleGeometry(Vector3 point1, Vector3 point2, float radius, string owner, out ShapeGeometry g, out Pose pose)
        {
            FieldCheck.Position(point1, owner, nameof(point1));
            FieldCheck.Position(point2, owner, nameof(point2));
            FieldCheck.Size(radius, owner, nameof(radius));
            Vector3 axis = point2 - point1;
            float length = axis.Length();
            Vector3 mid = 0.5f * (point1 + point2);
            if (length < 1e-6f)
            {
                g = ShapeGeometry.Sphere(radius);
                pose = new Pose(mid, Quaternion.Identity);
                return;
            }
            g = ShapeGeometry.Capsule(radius, 0.5f * length);
            pose = new Pose(mid, FromYTo(axis / length));
        }

        // The shortest-arc rotation taking +y to the unit vector u.
        static Quaternion FromYTo(Vector3 u)
        {
            float c = u.Y;
            if (c < -0.999999f) return new Quaternion(1, 0, 0, 0); // half a turn about x
            Vector3 axis = Vector3.Cross(Vector3.UnitY, u);
            return Quaternion.Normalize(new Quaternion(axis, 1f + c));
        }
    }
}
