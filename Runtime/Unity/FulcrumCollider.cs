#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// The base of the Unity collider faces: creates the headless collider on the shadow entity
    /// when enabled. As in Unity, the properties take effect at once on a live collider (set
    /// from code after AddComponent, or edited in the inspector in play mode); the headless
    /// collider checks every value. Also answers Unity's per-collider queries.
    /// </summary>
    public abstract class FulcrumCollider : FulcrumComponent
    {
        [SerializeField, Tooltip("Reports overlaps (IFulcrumTriggerHandler) with no physical response.")] bool m_IsTrigger;
        [SerializeField, Tooltip("Centre in the GameObject's frame, metres.")] Vector3 m_Center;
        [SerializeField, Tooltip("Friction used by Fulcrum (dynamic friction).")] float m_Friction = 0.6f;
        [SerializeField, Tooltip("Restitution in [0, 1].")] float m_Bounciness;

        F.Collider? _collider;
        FulcrumWorld? _world;

        /// <summary>A trigger reports overlaps and has no physical response.</summary>
        public bool isTrigger { get => m_IsTrigger; set { m_IsTrigger = value; Push(); } }

        /// <summary>The shape's centre in the GameObject's frame, metres.</summary>
        public Vector3 center { get => m_Center; set { m_Center = value; Push(); } }

        /// <summary>Friction (dynamic), &gt;= 0. Default: 0.6.</summary>
        public float friction { get => m_Friction; set { m_Friction = value; Push(); } }

        /// <summary>Restitution in [0, 1]. Default: 0.</summary>
        public float bounciness { get => m_Bounciness; set { m_Bounciness = value; Push(); } }

        /// <summary>The headless collider (null while disabled).</summary>
        public F.Collider? Collider => _collider;

        /// <summary>The rigidbody this collider belongs to (on this GameObject or a parent), or null for a static collider.</summary>
        public FulcrumRigidbody? attachedRigidbody => GetComponentInParent<FulcrumRigidbody>();

        /// <summary>Adds the concrete headless collider to the shadow entity.</summary>
        protected abstract F.Collider Create(F.Entity shadow);

        /// <summary>Copies the size fields (validated by the headless collider) to <paramref name="c"/>.</summary>
        protected abstract void PushShape(F.Collider c);

        /// <summary>Pushes every field to the live headless collider (no-op while disabled).</summary>
        protected void Push()
        {
            if (_collider != null && !_collider.isDestroyed) PushAll(_collider);
        }

        void OnEnable()
        {
            // A collider under a rigidbody whose OnEnable has not run yet still joins its body.
            FulcrumRigidbody? rb = attachedRigidbody;
            if (rb != null && rb.isActiveAndEnabled) rb.EnsureBody();
            _collider = Create(Shadow);
            PushAll(_collider);
            _world = FulcrumWorld.Instance;
            _world.Register(_collider, this);
        }

        void PushAll(F.Collider c)
        {
            PushShape(c);
            c.center = m_Center.ToNumerics();
            c.isTrigger = m_IsTrigger;
            if (m_Friction != 0.6f || m_Bounciness != 0f)
            {
                F.PhysicsMaterial m = c.material;
                m.dynamicFriction = m_Friction;
                m.bounciness = m_Bounciness;
            }
        }

        void OnValidate()
        {
            m_Friction = Mathf.Max(m_Friction, 0f);
            m_Bounciness = Mathf.Clamp01(m_Bounciness);
            ClampFields();
            if (IsLive) Push();
        }

        /// <summary>Clamps the size fields to what the headless collider accepts (inspector edits).</summary>
        protected virtual void ClampFields() { }

        void OnDisable()
        {
            if (_collider != null)
            {
                if (_world != null) _world.Unregister(_collider); // Unity's null check: not ?. on a UnityEngine.Object
                if (!_collider.isDestroyed) _collider.scene.DestroyImmediate(_collider);
            }
            _collider = null;
            ReleaseShadow();
        }

        /// <summary>This collider's own material (see <see cref="F.Collider.material"/>); null while disabled.</summary>
        public F.PhysicsMaterial? material
        {
            get => _collider?.material;
            set { if (_collider != null) _collider.material = value!; }
        }

        /// <summary>World bounds as of the last step, or an empty box while disabled.</summary>
        public Bounds bounds
        {
            get
            {
                if (_collider == null || _collider.shape.IsNone) return new Bounds(transform.position, Vector3.zero);
                Fulcrum.Mathematics.Aabb b = _collider.bounds;
                return new Bounds(b.Center.ToUnity(), b.Size.ToUnity());
            }
        }

        /// <summary>The ray's first hit with this collider alone (Unity's Collider.Raycast).</summary>
        public bool Raycast(Ray ray, out FulcrumRaycastHit hitInfo, float maxDistance)
        {
            hitInfo = default;
            if (_collider == null || !_collider.Raycast(new F.Ray(ray.origin.ToNumerics(), ray.direction.ToNumerics()), out F.RaycastHit hit, maxDistance)) return false;
            hitInfo = FulcrumRaycastHit.From(hit);
            return true;
        }

        /// <summary>The point of this collider closest to <paramref name="position"/>; the position itself when inside.</summary>
        public Vector3 ClosestPoint(Vector3 position) =>
            _collider != null ? _collider.ClosestPoint(position.ToNumerics()).ToUnity() : position;

        /// <summary>The point of <see cref="bounds"/> closest to <paramref name="position"/>.</summary>
        public Vector3 ClosestPointOnBounds(Vector3 position) =>
            _collider != null ? _collider.ClosestPointOnBounds(position.ToNumerics()).ToUnity() : position;
    }
}
