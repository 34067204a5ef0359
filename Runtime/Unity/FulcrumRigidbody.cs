#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Unity face of <see cref="F.Rigidbody"/>: the serialized fields are copied to the headless
    /// component when it is enabled; the properties take effect at once (from code, or edited in
    /// the inspector in play mode) and the other members forward to <see cref="Body"/>, where
    /// every value is checked and documented. Members Unity has and this face lacks are on <see cref="Body"/>.
    /// </summary>
    [DisallowMultipleComponent]
    public sealed class FulcrumRigidbody : FulcrumComponent
    {
        [SerializeField, Tooltip("Mass, kg (> 0).")] float m_Mass = 1f;
        [SerializeField, Tooltip("Linear damping, 1/s (Unity 2021-2022: drag).")] float m_LinearDamping;
        [SerializeField, Tooltip("Angular damping, 1/s (Unity 2021-2022: angularDrag).")] float m_AngularDamping = 0.05f;
        [SerializeField] bool m_UseGravity = true;
        [SerializeField] bool m_IsKinematic;
        [SerializeField] F.RigidbodyInterpolation m_Interpolation = F.RigidbodyInterpolation.None;
        [SerializeField] F.CollisionDetectionMode m_CollisionDetectionMode = F.CollisionDetectionMode.Discrete;
        [SerializeField] F.RigidbodyConstraints m_Constraints = F.RigidbodyConstraints.None;

        /// <summary>Mass, kg (&gt; 0).</summary>
        public float mass { get => m_Mass; set { m_Mass = value; Push(); } }
        /// <summary>Linear damping, 1/s.</summary>
        public float linearDamping { get => m_LinearDamping; set { m_LinearDamping = value; Push(); } }
        /// <summary>Angular damping, 1/s.</summary>
        public float angularDamping { get => m_AngularDamping; set { m_AngularDamping = value; Push(); } }
        /// <summary>Whether gravity acts on the body.</summary>
        public bool useGravity { get => m_UseGravity; set { m_UseGravity = value; Push(); } }
        /// <summary>Kinematic bodies are moved by the game and push dynamic ones.</summary>
        public bool isKinematic { get => m_IsKinematic; set { m_IsKinematic = value; Push(); } }
        /// <summary>How the transform shows the body between fixed steps.</summary>
        public F.RigidbodyInterpolation interpolation { get => m_Interpolation; set { m_Interpolation = value; Push(); } }
        /// <summary>Discrete or continuous collision detection.</summary>
        public F.CollisionDetectionMode collisionDetectionMode { get => m_CollisionDetectionMode; set { m_CollisionDetectionMode = value; Push(); } }
        /// <summary>Frozen degrees of freedom (see <see cref="F.Rigidbody.constraints"/>).</summary>
        public F.RigidbodyConstraints constraints { get => m_Constraints; set { m_Constraints = value; Push(); } }

        F.Rigidbody? _body;

        /// <summary>The headless rigidbody (null while disabled).</summary>
        public F.Rigidbody? Body => _body;

        void OnEnable()
        {
            EnsureBody();
            FulcrumWorld.Instance.OnBodyEnabled(this);
        }

        /// <summary>Creates the headless rigidbody if it is not there yet (joints call it: their OnEnable may run first).</summary>
        internal F.Rigidbody EnsureBody()
        {
            if (_body != null && !_body.isDestroyed) return _body;
            _body = Shadow.AddComponent<F.Rigidbody>();
            Push(_body);
            return _body;
        }

        void Push()
        {
            if (_body != null && !_body.isDestroyed) Push(_body);
        }

        void Push(F.Rigidbody b)
        {
            b.mass = m_Mass;
            b.linearDamping = m_LinearDamping;
            b.angularDamping = m_AngularDamping;
            b.useGravity = m_UseGravity;
            b.isKinematic = m_IsKinematic;
            b.interpolation = m_Interpolation;
            b.collisionDetectionMode = m_CollisionDetectionMode;
            b.constraints = m_Constraints;
        }

        void OnValidate()
        {
            m_Mass = Mathf.Max(m_Mass, Limits.MinMass);
            m_LinearDamping = Mathf.Max(m_LinearDamping, 0f);
            m_AngularDamping = Mathf.Max(m_AngularDamping, 0f);
            if (IsLive) Push();
        }

        void OnDisable()
        {
            if (_body != null && !_body.isDestroyed) _body.scene.DestroyImmediate(_body);
            _body = null;
            ReleaseShadow();
        }

        /// <summary>See <see cref="F.Rigidbody.AddForce(System.Numerics.Vector3, Fulcrum.ForceMode)"/>.</summary>
        public void AddForce(Vector3 force, UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) => _body?.AddForce(force.ToNumerics(), mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.AddRelativeForce"/>.</summary>
        public void AddRelativeForce(Vector3 force, UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) => _body?.AddRelativeForce(force.ToNumerics(), mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.AddTorque"/>.</summary>
        public void AddTorque(Vector3 torque, UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) => _body?.AddTorque(torque.ToNumerics(), mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.AddRelativeTorque"/>.</summary>
        public void AddRelativeTorque(Vector3 torque, UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) => _body?.AddRelativeTorque(torque.ToNumerics(), mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.AddForceAtPosition"/>.</summary>
        public void AddForceAtPosition(Vector3 force, Vector3 position, UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) =>
            _body?.AddForceAtPosition(force.ToNumerics(), position.ToNumerics(), mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.AddExplosionForce"/>.</summary>
        public void AddExplosionForce(float explosionForce, Vector3 explosionPosition, float explosionRadius, float upwardsModifier = 0f,
            UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) =>
            _body?.AddExplosionForce(explosionForce, explosionPosition.ToNumerics(), explosionRadius, upwardsModifier, mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.MovePosition"/>.</summary>
        public void MovePosition(Vector3 position) => _body?.MovePosition(position.ToNumerics());

        /// <summary>See <see cref="F.Rigidbody.MoveRotation"/>.</summary>
        public void MoveRotation(Quaternion rotation) => _body?.MoveRotation(rotation.ToNumerics());

        /// <summary>See <see cref="F.Rigidbody.Sleep"/>.</summary>
        public void Sleep() => _body?.Sleep();

        /// <summary>See <see cref="F.Rigidbody.WakeUp"/>.</summary>
        public void WakeUp() => _body?.WakeUp();

        /// <summary>See <see cref="F.Rigidbody.IsSleeping"/>.</summary>
        public bool IsSleeping() => _body == null || _body.IsSleeping();

        /// <summary>See <see cref="F.Rigidbody.SweepTest"/>; the hit is reported with the Unity collider.</summary>
        public bool SweepTest(Vector3 direction, out FulcrumRaycastHit hitInfo, float maxDistance = Mathf.Infinity,
            F.QueryTriggerInteraction queryTriggerInteraction = F.QueryTriggerInteraction.UseGlobal)
        {
            hitInfo = default;
            if (_body == null || !_body.SweepTest(direction.ToNumerics(), out F.RaycastHit hit, maxDistance, queryTriggerInteraction)) return false;
            hitInfo = FulcrumRaycastHit.From(hit);
            return true;
        }

        /// <summary>Velocity of the centre of mass, m/s.</summary>
        public Vector3 linearVelocity
        {
            get => _body != null ? _body.linearVelocity.ToUnity() : Vector3.zero;
            set { if (_body != null) _body.linearVelocity = value.ToNumerics(); }
        }

        /// <summary>Unity 2021.3-2022's name of <see cref="linearVelocity"/>.</summary>
        public Vector3 velocity
        {
            get => linearVelocity;
            set => linearVelocity = value;
        }

        /// <summary>Angular velocity, rad/s.</summary>
        public Vector3 angularVelocity
        {
            get => _body != null ? _body.angularVelocity.ToUnity() : Vector3.zero;
            set { if (_body != null) _body.angularVelocity = value.ToNumerics(); }
        }

        /// <summary>Unity 2021.3-2022's name of <see cref="linearDamping"/>.</summary>
        public float drag { get => linearDamping; set => linearDamping = value; }

        /// <summary>Unity 2021.3-2022's name of <see cref="angularDamping"/>.</summary>
        public float angularDrag { get => angularDamping; set => angularDamping = value; }

        /// <summary>See <see cref="F.Rigidbody.freezeRotation"/>.</summary>
        public bool freezeRotation
        {
            get => (m_Constraints & F.RigidbodyConstraints.FreezeRotation) == F.RigidbodyConstraints.FreezeRotation;
            set => constraints = value ? m_Constraints | F.RigidbodyConstraints.FreezeRotation : m_Constraints & ~F.RigidbodyConstraints.FreezeRotation;
        }

        /// <summary>See <see cref="F.Rigidbody.maxAngularVelocity"/> (default: no cap; Unity's is 7 rad/s).</summary>
        public float maxAngularVelocity
        {
            get => _body != null ? _body.maxAngularVelocity : float.PositiveInfinity;
            set { if (_body != null) _body.maxAngularVelocity = value; }
        }

        /// <summary>See <see cref="F.Rigidbody.maxLinearVelocity"/>.</summary>
        public float maxLinearVelocity
        {
            get => _body != null ? _body.maxLinearVelocity : float.PositiveInfinity;
            set { if (_body != null) _body.maxLinearVelocity = value; }
        }

        /// <summary>See <see cref="F.Rigidbody.detectCollisions"/>.</summary>
        public bool detectCollisions
        {
            get => _body == null || _body.detectCollisions;
            set { if (_body != null) _body.detectCollisions = value; }
        }

        /// <summary>World centre of mass.</summary>
        public Vector3 worldCenterOfMass => _body != null ? _body.worldCenterOfMass.ToUnity() : transform.position;

        /// <summary>Velocity of the body's material point at a world position, m/s.</summary>
        public Vector3 GetPointVelocity(Vector3 worldPoint) => _body != null ? _body.GetPointVelocity(worldPoint.ToNumerics()).ToUnity() : Vector3.zero;
    }
}
