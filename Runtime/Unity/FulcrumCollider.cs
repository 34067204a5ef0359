#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>The base of the Unity collider faces: creates the headless collider on the shadow entity when enabled.</summary>
    public abstract class FulcrumCollider : FulcrumComponent
    {
        [Tooltip("Reports overlaps (OnFulcrumTrigger*) with no physical response.")] public bool isTrigger;
        [Tooltip("Centre in the GameObject's frame, metres.")] public Vector3 center;
        [Tooltip("Friction used by Fulcrum (dynamic friction).")] public float friction = 0.6f;
        [Tooltip("Restitution in [0, 1].")] public float bounciness;

        F.Collider? _collider;

        /// <summary>The headless collider (null while disabled).</summary>
        public F.Collider? Collider => _collider;

        /// <summary>Adds the concrete headless collider and sets its size fields.</summary>
        protected abstract F.Collider Create(F.Entity shadow);

        void OnEnable()
        {
            _collider = Create(Shadow);
            _collider.center = center.ToNumerics();
            _collider.isTrigger = isTrigger;
            if (friction != 0.6f || bounciness != 0f)
                _collider.sharedMaterial = new F.PhysicsMaterial(name) { dynamicFriction = friction, bounciness = bounciness };
        }

        void OnDisable()
        {
            if (_collider != null && !_collider.isDestroyed) _collider.scene.DestroyImmediate(_collider);
            _collider = null;
            ReleaseShadow();
        }
    }
}
