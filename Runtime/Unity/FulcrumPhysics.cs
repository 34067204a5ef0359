#nullable enable
using System;
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Scene queries in the shape of Unity's static Physics class, on the loaded scene's
    /// <see cref="FulcrumWorld"/> (created if missing): the same names, parameters and defaults,
    /// with Fulcrum's collider and hit types. The NonAlloc forms and the Check forms allocate
    /// nothing once warm; the forms returning arrays allocate, as Unity's do.
    /// </summary>
    public static class FulcrumPhysics
    {
        /// <summary>Unity's Physics.DefaultRaycastLayers: every layer but Ignore Raycast.</summary>
        public const int DefaultRaycastLayers = F.PhysicsScene.DefaultRaycastLayers;

        /// <summary>Unity's Physics.AllLayers.</summary>
        public const int AllLayers = ~0;

        static F.Collider[] s_colliders = new F.Collider[16];
        static F.RaycastHit[] s_hits = new F.RaycastHit[16];

        static F.PhysicsScene Scene => FulcrumWorld.Instance.Scene;

        /// <summary>World gravity, m/s^2.</summary>
        public static Vector3 gravity
        {
            get => FulcrumWorld.Instance.gravity;
            set => FulcrumWorld.Instance.gravity = value;
        }

        /// <summary>The first collider along the ray (Unity's Physics.Raycast).</summary>
        public static bool Raycast(Vector3 origin, Vector3 direction, out FulcrumRaycastHit hitInfo, float maxDistance = Mathf.Infinity,
            int layerMask = DefaultRaycastLayers, F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            hitInfo = default;
            if (!Scene.Raycast(origin.ToNumerics(), direction.ToNumerics(), out F.RaycastHit hit, maxDistance, layerMask, queryTriggerInteraction)) return false;
            hitInfo = FulcrumRaycastHit.From(hit);
            return true;
        }

        /// <summary>Whether anything lies along the ray.</summary>
        public static bool Raycast(Vector3 origin, Vector3 direction, float maxDistance = Mathf.Infinity,
            int layerMask = DefaultRaycastLayers, F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal) =>
            Raycast(origin, direction, out _, maxDistance, layerMask, queryTriggerInteraction);

        /// <summary>The first collider along <paramref name="ray"/>.</summary>
        public static bool Raycast(Ray ray, out FulcrumRaycastHit hitInfo, float maxDistance = Mathf.Infinity,
            int layerMask = DefaultRaycastLayers, F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal) =>
            Raycast(ray.origin, ray.direction, out hitInfo, maxDistance, layerMask, queryTriggerInteraction);

        /// <summary>Every collider along the ray, nearest first, in a new array (Unity's RaycastAll).</summary>
        public static FulcrumRaycastHit[] RaycastAll(Vector3 origin, Vector3 direction, float maxDistance = Mathf.Infinity,
            int layerMask = DefaultRaycastLayers, F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            F.RaycastHit[] hits = Scene.RaycastAll(origin.ToNumerics(), direction.ToNumerics(), maxDistance, layerMask, queryTriggerInteraction);
            var result = new FulcrumRaycastHit[hits.Length];
            for (int i = 0; i < hits.Length; i++) result[i] = FulcrumRaycastHit.From(hits[i]);
            return result;
        }

        /// <summary>Every collider along the ray, nearest first, into <paramref name="results"/>; returns how many (Unity's RaycastNonAlloc).</summary>
        public static int RaycastNonAlloc(Vector3 origin, Vector3 direction, FulcrumRaycastHit[] results, float maxDistance = Mathf.Infinity,
            int layerMask = DefaultRaycastLayers, F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            if (results == null) throw new ArgumentNullException(nameof(results));
            if (s_hits.Length < results.Length) s_hits = new F.RaycastHit[results.Length];
            int n = Scene.RaycastNonAlloc(origin.ToNumerics(), direction.ToNumerics(), new Span<F.RaycastHit>(s_hits, 0, results.Length), maxDistance, layerMask, queryTriggerInteraction);
            for (int i = 0; i < n; i++) results[i] = FulcrumRaycastHit.From(s_hits[i]);
            return n;
        }

        /// <summary>Sweeps a sphere (Unity's Physics.SphereCast).</summary>
        public static bool SphereCast(Vector3 origin, float radius, Vector3 direction, out FulcrumRaycastHit hitInfo, float maxDistance = Mathf.Infinity,
            int layerMask = DefaultRaycastLayers, F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            hitInfo = default;
            if (!Scene.SphereCast(origin.ToNumerics(), radius, direction.ToNumerics(), out F.RaycastHit hit, maxDistance, layerMask, queryTriggerInteraction)) return false;
            hitInfo = FulcrumRaycastHit.From(hit);
            return true;
        }

        /// <summary>Sweeps a box (Unity's Physics.BoxCast).</summary>
        public static bool BoxCast(Vector3 center, Vector3 halfExtents, Vector3 direction, out FulcrumRaycastHit hitInfo, Quaternion orientation,
            float maxDistance = Mathf.Infinity, int layerMask = DefaultRaycastLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            hitInfo = default;
            if (!Scene.BoxCast(center.ToNumerics(), halfExtents.ToNumerics(), direction.ToNumerics(), out F.RaycastHit hit, orientation.ToNumerics(),
                    maxDistance, layerMask, queryTriggerInteraction)) return false;
            hitInfo = FulcrumRaycastHit.From(hit);
            return true;
        }

        /// <summary>Sweeps a capsule between two hemisphere centres (Unity's Physics.CapsuleCast).</summary>
        public static bool CapsuleCast(Vector3 point1, Vector3 point2, float radius, Vector3 direction, out FulcrumRaycastHit hitInfo,
            float maxDistance = Mathf.Infinity, int layerMask = DefaultRaycastLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            hitInfo = default;
            if (!Scene.CapsuleCast(point1.ToNumerics(), point2.ToNumerics(), radius, direction.ToNumerics(), out F.RaycastHit hit,
                    maxDistance, layerMask, queryTriggerInteraction)) return false;
            hitInfo = FulcrumRaycastHit.From(hit);
            return true;
        }

        /// <summary>The colliders overlapping a sphere, in a new array (Unity's OverlapSphere).</summary>
        public static FulcrumCollider[] OverlapSphere(Vector3 position, float radius, int layerMask = AllLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal) =>
            Faces(Scene.OverlapSphere(position.ToNumerics(), radius, layerMask, queryTriggerInteraction));

        /// <summary>The colliders overlapping a sphere, into <paramref name="results"/> (Unity's OverlapSphereNonAlloc).</summary>
        public static int OverlapSphereNonAlloc(Vector3 position, float radius, FulcrumCollider[] results, int layerMask = AllLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            int n = Scene.OverlapSphere(position.ToNumerics(), radius, Scratch(results), layerMask, queryTriggerInteraction);
            return Faces(n, results);
        }

        /// <summary>The colliders overlapping a box, in a new array (Unity's OverlapBox).</summary>
        public static FulcrumCollider[] OverlapBox(Vector3 center, Vector3 halfExtents, Quaternion orientation, int layerMask = AllLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal) =>
            Faces(Scene.OverlapBox(center.ToNumerics(), halfExtents.ToNumerics(), orientation.ToNumerics(), layerMask, queryTriggerInteraction));

        /// <summary>The colliders overlapping a box, into <paramref name="results"/> (Unity's OverlapBoxNonAlloc).</summary>
        public static int OverlapBoxNonAlloc(Vector3 center, Vector3 halfExtents, FulcrumCollider[] results, Quaternion orientation, int layerMask = AllLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            int n = Scene.OverlapBox(center.ToNumerics(), halfExtents.ToNumerics(), Scratch(results), orientation.ToNumerics(), layerMask, queryTriggerInteraction);
            return Faces(n, results);
        }

        /// <summary>The colliders overlapping a capsule, in a new array (Unity's OverlapCapsule).</summary>
        public static FulcrumCollider[] OverlapCapsule(Vector3 point0, Vector3 point1, float radius, int layerMask = AllLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal) =>
            Faces(Scene.OverlapCapsule(point0.ToNumerics(), point1.ToNumerics(), radius, layerMask, queryTriggerInteraction));

        /// <summary>The colliders overlapping a capsule, into <paramref name="results"/> (Unity's OverlapCapsuleNonAlloc).</summary>
        public static int OverlapCapsuleNonAlloc(Vector3 point0, Vector3 point1, float radius, FulcrumCollider[] results, int layerMask = AllLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            int n = Scene.OverlapCapsule(point0.ToNumerics(), point1.ToNumerics(), radius, Scratch(results), layerMask, queryTriggerInteraction);
            return Faces(n, results);
        }

        /// <summary>Whether any collider overlaps the sphere (Unity's CheckSphere).</summary>
        public static bool CheckSphere(Vector3 position, float radius, int layerMask = DefaultRaycastLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal) =>
            Scene.CheckSphere(position.ToNumerics(), radius, layerMask, queryTriggerInteraction);

        /// <summary>Whether any collider overlaps the box (Unity's CheckBox).</summary>
        public static bool CheckBox(Vector3 center, Vector3 halfExtents, Quaternion orientation, int layerMask = DefaultRaycastLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal) =>
            Scene.CheckBox(center.ToNumerics(), halfExtents.ToNumerics(), orientation.ToNumerics(), layerMask, queryTriggerInteraction);

        /// <summary>Whether any collider overlaps the capsule (Unity's CheckCapsule).</summary>
        public static bool CheckCapsule(Vector3 start, Vector3 end, float radius, int layerMask = DefaultRaycastLayers,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal) =>
            Scene.CheckCapsule(start.ToNumerics(), end.ToNumerics(), radius, layerMask, queryTriggerInteraction);

        /// <summary>The point of <paramref name="collider"/>, placed at the given pose, closest to <paramref name="point"/> (Unity's Physics.ClosestPoint).</summary>
        public static Vector3 ClosestPoint(Vector3 point, FulcrumCollider collider, Vector3 position, Quaternion rotation) =>
            Scene.ClosestPoint(point.ToNumerics(), Live(collider), position.ToNumerics(), rotation.ToNumerics()).ToUnity();

        /// <summary>The shortest translation that separates two colliders at the given poses (Unity's Physics.ComputePenetration).</summary>
        public static bool ComputePenetration(FulcrumCollider colliderA, Vector3 positionA, Quaternion rotationA,
            FulcrumCollider colliderB, Vector3 positionB, Quaternion rotationB, out Vector3 direction, out float distance)
        {
            bool hit = Scene.ComputePenetration(Live(colliderA), positionA.ToNumerics(), rotationA.ToNumerics(),
                Live(colliderB), positionB.ToNumerics(), rotationB.ToNumerics(), out System.Numerics.Vector3 d, out distance);
            direction = d.ToUnity();
            return hit;
        }

        /// <summary>Makes two colliders ignore each other or collide again (Unity's Physics.IgnoreCollision).</summary>
        public static void IgnoreCollision(FulcrumCollider collider1, FulcrumCollider collider2, bool ignore = true) =>
            Scene.IgnoreCollision(Live(collider1), Live(collider2), ignore);

        /// <summary>Whether two colliders ignore each other (Unity's Physics.GetIgnoreCollision).</summary>
        public static bool GetIgnoreCollision(FulcrumCollider collider1, FulcrumCollider collider2) =>
            Scene.GetIgnoreCollision(Live(collider1), Live(collider2));

        /// <summary>Makes two layers ignore each other or collide again (Unity's Physics.IgnoreLayerCollision).</summary>
        public static void IgnoreLayerCollision(int layer1, int layer2, bool ignore = true) => Scene.IgnoreLayerCollision(layer1, layer2, ignore);

        static F.Collider Live(FulcrumCollider c)
        {
            if (c == null) throw new ArgumentNullException(nameof(c));
            return c.Collider ?? throw new InvalidOperationException($"{c.name}: the collider is disabled (it has no headless collider).");
        }

        static Span<F.Collider> Scratch(FulcrumCollider[] results)
        {
            if (results == null) throw new ArgumentNullException(nameof(results));
            if (s_colliders.Length < results.Length) s_colliders = new F.Collider[results.Length];
            return new Span<F.Collider>(s_colliders, 0, results.Length);
        }

        static int Faces(int n, FulcrumCollider[] results)
        {
            FulcrumWorld w = FulcrumWorld.Instance;
            int kept = 0;
            for (int i = 0; i < n; i++)
            {
                FulcrumCollider? face = w.FaceOf(s_colliders[i]);
                if (face != null) results[kept++] = face;
            }
            return kept;
        }

        static FulcrumCollider[] Faces(F.Collider[] colliders)
        {
            FulcrumWorld w = FulcrumWorld.Instance;
            int kept = 0;
            var faces = new FulcrumCollider[colliders.Length];
            foreach (F.Collider c in colliders)
            {
                FulcrumCollider? face = w.FaceOf(c);
                if (face != null) faces[kept++] = face;
            }
            if (kept < faces.Length) Array.Resize(ref faces, kept);
            return faces;
        }
    }
}
