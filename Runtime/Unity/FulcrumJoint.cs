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
        [SerializeField, Tooltip("The other body; none = the world.")] FulcrumRigidbody? m_ConnectedBody;
        [SerializeField, Tooltip("The joint point in this GameObject's frame, metres.")] Vector3 m_Anchor;
        [SerializeField, Tooltip("The joint point in the connected body's frame (a world point without one).")] Vector3 m_ConnectedAnchor;
        [SerializeField] bool m_AutoConfigureConnectedAnchor = true;
        [SerializeField, Tooltip("The joint axis in this GameObject's frame.")] Vector3 m_Axis = Vector3.right;
        [SerializeField, Tooltip("Force that breaks the joint, N (Infinity = unbreakable).")] float m_BreakForce = Mathf.Infinity;
        [SerializeField, Tooltip("Torque that breaks the joint, N m (Infinity = unbreakable).")] float m_BreakTorque = Mathf.Infinity;
        [SerializeField, Tooltip("Whether the two bodies still collide with each other.")] bool m_EnableCollision;

        /// <summary>The other body; null = the world. Changing it on a live joint rebuilds it at the current pose.</summary>
        public FulcrumRigidbody? connectedBody { get => m_ConnectedBody; set { m_ConnectedBody = value; Push(); } }
        /// <summary>The joint point in this GameObject's frame, metres.</summary>
        public Vector3 anchor { get => m_Anchor; set { m_Anchor = value; Push(); } }
        /// <summary>The joint point in the connected body's frame (a world point without one); computed while <see cref="autoConfigureConnectedAnchor"/>.</summary>
        public Vector3 connectedAnchor
        {
            get => _joint != null && m_AutoConfigureConnectedAnchor ? _joint.connectedAnchor.ToUnity() : m_ConnectedAnchor;
            set { m_ConnectedAnchor = value; Push(); }
        }
        /// <summary>Whether the connected anchor is computed so that the joint starts satisfied.</summary>
        public bool autoConfigureConnectedAnchor { get => m_AutoConfigureConnectedAnchor; set { m_AutoConfigureConnectedAnchor = value; Push(); } }
        /// <summary>The joint axis in this GameObject's frame.</summary>
        public Vector3 axis { get => m_Axis; set { m_Axis = value; Push(); } }
        /// <summary>Force that breaks the joint, N.</summary>
        public float breakForce { get => m_BreakForce; set { m_BreakForce = value; Push(); } }
        /// <summary>Torque that breaks the joint, N m.</summary>
        public float breakTorque { get => m_BreakTorque; set { m_BreakTorque = value; Push(); } }
        /// <summary>Whether the two bodies still collide with each other.</summary>
        public bool enableCollision { get => m_EnableCollision; set { m_EnableCollision = value; Push(); } }

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
            FulcrumWorld.Instance.Register(this);
        }

        /// <summary>Connects to <see cref="connectedBody"/> again (it was enabled after this joint).</summary>
        internal void Reconnect() => Push();

        /// <summary>Pushes every field to the live headless joint (no-op while disabled).</summary>
        protected void Push()
        {
            if (_joint != null && !_joint.isDestroyed) PushAll(_joint);
        }

        void PushAll(F.Joint j)
        {
            F.Rigidbody? other = m_ConnectedBody != null && m_ConnectedBody.isActiveAndEnabled ? m_ConnectedBody.EnsureBody() : null;
            if (j.connectedBody != other) j.connectedBody = other;
            if (j.anchor != m_Anchor.ToNumerics()) j.anchor = m_Anchor.ToNumerics();
            if (j.autoConfigureConnectedAnchor != m_AutoConfigureConnectedAnchor) j.autoConfigureConnectedAnchor = m_AutoConfigureConnectedAnchor;
            if (!m_AutoConfigureConnectedAnchor && j.connectedAnchor != m_ConnectedAnchor.ToNumerics()) j.connectedAnchor = m_ConnectedAnchor.ToNumerics();
            if (j.axis != m_Axis.ToNumerics()) j.axis = m_Axis.ToNumerics();
            j.breakForce = m_BreakForce;
            j.breakTorque = m_BreakTorque;
            j.enableCollision = m_EnableCollision;
            PushKind(j);
        }

        void OnValidate()
        {
            m_BreakForce = Mathf.Max(m_BreakForce, 0f);
            m_BreakTorque = Mathf.Max(m_BreakTorque, 0f);
            if (m_Axis == Vector3.zero) m_Axis = Vector3.right;
            if (IsLive) Push();
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
            FulcrumWorld? world = FulcrumWorld.Current; // Unity's null check: not ?. on a UnityEngine.Object
            if (world != null) world.Unregister(this);
            if (_joint != null && !_joint.isDestroyed) _joint.scene.DestroyImmediate(_joint);
            _joint = null;
            ReleaseShadow();
        }
    }
}
