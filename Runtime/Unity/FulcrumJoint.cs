#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// The base of the Unity joint faces (Unity's Joint): ties this GameObject's
    /// <see cref="FulcrumRigidbody"/> to <see cref="connectedBody"/> (or to the world when none).
    /// The joint's rest pose is the bodies' pose when it is enabled. A joint that breaks
    /// (<see cref="breakForce"/>, <see cref="breakTorque"/>) sends OnFulcrumJointBreak and this
    /// component is destroyed, as in Unity.
    /// </summary>
    [RequireComponent(typeof(FulcrumRigidbody))]
    public abstract class FulcrumJoint : FulcrumComponent
    {
        [Tooltip("The other body; none = the world.")] public FulcrumRigidbody? connectedBody;
        [Tooltip("The joint point in this GameObject's frame, metres.")] public Vector3 anchor;
        [Tooltip("The joint point in the connected body's frame (a world point without one).")] public Vector3 connectedAnchor;
        public bool autoConfigureConnectedAnchor = true;
        [Tooltip("The joint axis in this GameObject's frame.")] public Vector3 axis = Vector3.right;
        [Tooltip("Force that breaks the joint, N (Infinity = unbreakable).")] public float breakForce = Mathf.Infinity;
        [Tooltip("Torque that breaks the joint, N m (Infinity = unbreakable).")] public float breakTorque = Mathf.Infinity;
        [Tooltip("Whether the two bodies still collide with each other.")] public bool enableCollision;

        F.Joint? _joint;

        /// <summary>The headless joint (null while disabled).</summary>
        public F.Joint? Joint => _joint;

        /// <summary>Force the joint applies, N, as of the last step.</summary>
        public Vector3 currentForce => _joint != null ? _joint.currentForce.ToUnity() : Vector3.zero;

        /// <summary>Torque the joint applies, N m, as of the last step.</summary>
        public Vector3 currentTorque => _joint != null ? _joint.currentTorque.ToUnity() : Vector3.zero;

        /// <summary>Adds the concrete headless joint to the shadow entity.</summary>
        protected abstract F.Joint Create(F.Entity shadow);

        /// <summary>Copies the kind's own fields to <paramref name="j"/>.</summary>
        protected abstract void PushKind(F.Joint j);

        void OnEnable()
        {
            GetComponent<FulcrumRigidbody>().EnsureBody();
            _joint = Create(Shadow);
            PushAll(_joint);
        }

        void PushAll(F.Joint j)
        {
            j.connectedBody = connectedBody != null && connectedBody.isActiveAndEnabled ? connectedBody.EnsureBody() : null;
            j.anchor = anchor.ToNumerics();
            j.autoConfigureConnectedAnchor = autoConfigureConnectedAnchor;
            if (!autoConfigureConnectedAnchor) j.connectedAnchor = connectedAnchor.ToNumerics();
            j.axis = axis.ToNumerics();
            j.breakForce = breakForce;
            j.breakTorque = breakTorque;
            j.enableCollision = enableCollision;
            PushKind(j);
        }

        void OnValidate()
        {
            breakForce = Mathf.Max(breakForce, 0f);
            breakTorque = Mathf.Max(breakTorque, 0f);
            if (axis == Vector3.zero) axis = Vector3.right;
            if (IsLive && _joint != null && !_joint.isDestroyed) PushAll(_joint);
        }

        // A broken joint's headless component is destroyed by the scene: this face follows.
        void FixedUpdate()
        {
            if (_joint != null && _joint.isDestroyed)
            {
                _joint = null;
                Destroy(this);
            }
        }

        void OnDisable()
        {
            if (_joint != null && !_joint.isDestroyed) _joint.scene.DestroyImmediate(_joint);
            _joint = null;
            ReleaseShadow();
        }
    }
}
