using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Mathematics;

namespace Fulcrum.Components
{
    public sealed partial class Rigidbody
    {
        /// <summary>
        /// Sweeps every collider of the body along <paramref name="direction"/> as if the body
        /// moved there, and reports the first collider of another body it would touch within
        /// <paramref name="maxDistance"/> (Unity's SweepTest; distance is how far the body
        /// travelled). The body's own colliders and triggers (unless asked) are ignored; colliders
        /// overlapping at the start are not reported. Allocates nothing.
        /// </summary>
        public bool SweepTest(Vector3 direction, out RaycastHit hitInfo, float maxDistance = float.PositiveInfinity,
            QueryTriggerInteraction queryTriggerInteraction = QueryTriggerInteraction.UseGlobal)
        {
            ThrowIfDestroyed();
            FieldCheck.Finite(direction, this, nameof(direction));
            if (direction.LengthSquared() < 1e-24f) throw new ArgumentException($"{this}: direction must be non-zero.", nameof(direction));
            if (float.IsNaN(maxDistance) || maxDistance < 0) throw new ArgumentException($"{this}: maxDistance must be >= 0, got {maxDistance}.", nameof(maxDistance));
            hitInfo = default;
            if (!HasBody) return false;
            PhysicsScene s = scene;
            if (s.world.IsStepping) throw new InvalidOperationException($"{this}: SweepTest cannot run while the world steps (from a callback inside World.Step).");
            QueryFilter filter = s.Filter(PhysicsScene.DefaultRaycastLayers, queryTriggerInteraction);
            filter.IgnoreBody = _body;
            Pose bodyPose = World.GetBody(_body).Pose;
            bool any = false;
            float best = float.PositiveInfinity;
            for (int k = 0; k < Colliders.Count; k++)
            {
                Collider c = Colliders[k];
                if (!c.HasShape || c.isTrigger) continue;
                ShapeGeometry g = World.GetShapeGeometry(c.shape);
                Pose pose = bodyPose * World.GetShapeLocalPose(c.shape);
                if (!World.ShapeCast(g, pose, direction, Math.Min(maxDistance, best), filter, out ShapeCastHit hit)) continue;
                if (hit.Distance >= best) continue;
                if (!s.ToHit(hit.Shape, hit.Point, hit.Normal, hit.Distance, out RaycastHit h)) continue;
                best = hit.Distance;
                hitInfo = h;
                any = true;
            }
            return any;
        }
    }
}
