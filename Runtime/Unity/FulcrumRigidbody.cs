#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Unity face of <see cref="F.Rigidbody"/>: the inspector fields are copied to the headless
    /// component when it is enabled; at run time use <see cref="Body"/> (or the forwarding
    /// methods) so that every value is checked and documented in one place.
    /// </summary>
    [DisallowMultipleComponent]
    public sealed class FulcrumRigidbody : FulcrumComponent
    {
        [Tooltip("Mass, kg (> 0).")] public float mass = 1f;
        [Tooltip("Linear damping, 1/s.")] public float linearDamping;
        [Tooltip("Angular damping, 1/s.")] public float angularDamping = 0.05f;
        public bool useGravity = true;
        public bool isKinematic;
        public F.RigidbodyInterpolation interpolation = F.RigidbodyInterpolation.None;
        public F.CollisionDetectionMode collisionDetectionMode = F.CollisionDetectionMode.Discrete;
        public F.RigidbodyConstraints constraints = F.RigidbodyConstraints.None;

        F.Rigidbody? _body;

        /// <summary>The headless rigidbody (null while disabled).</summary>
        public F.Rigidbody? Body => _body;

        void OnEnable()
        {
            _body = Shadow.AddComponent<F.Rigidbody>();
            _body.mass = mass;
            _body.linearDamping = linearDamping;
            _body.angularDamping = angularDamping;
            _body.useGravity = useGravity;
            _body.isKinematic = isKinematic;
            _body.interpolation = interpolation;
            _body.collisionDetectionMode = collisionDetectionMode;
            _body.constraints = constraints;
        }

        void OnDisable()
        {
            if (_body != null && !_body.isDestroyed) _body.scene.DestroyImmediate(_body);
            _body = null;
            ReleaseShadow();
        }

        /// <summary>See <see cref="F.Rigidbody.AddForce(System.Numerics.Vector3, Fulcrum.ForceMode)"/>.</summary>
        public void AddForce(Vector3 force, UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) => _body?.AddForce(force.ToNumerics(), mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.AddTorque"/>.</summary>
        public void AddTorque(Vector3 torque, UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) => _body?.AddTorque(torque.ToNumerics(), mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.AddForceAtPosition"/>.</summary>
        public void AddForceAtPosition(Vector3 force, Vector3 position, UnityEngine.ForceMode mode = UnityEngine.ForceMode.Force) =>
            _body?.AddForceAtPosition(force.ToNumerics(), position.ToNumerics(), mode.ToFulcrum());

        /// <summary>See <see cref="F.Rigidbody.MovePosition"/>.</summary>
        public void MovePosition(Vector3 position) => _body?.MovePosition(position.ToNumerics());

        /// <summary>See <see cref="F.Rigidbody.MoveRotation"/>.</summary>
        public void MoveRotation(Quaternion rotation) => _body?.MoveRotation(rotation.ToNumerics());

        /// <summary>Velocity of the centre of mass, m/s.</summary>
        public Vector3 linearVelocity
        {
            get => _body != null ? _body.linearVelocity.ToUnity() : Vector3.zero;
            set { if (_body != null) _body.linearVelocity = value.ToNumerics(); }
        }

        /// <summary>Angular velocity, rad/s.</summary>
        public Vector3 angularVelocity
        {
            get => _body != null ? _body.angularVelocity.ToUnity() : Vector3.zero;
            set { if (_body != null) _body.angularVelocity = value.ToNumerics(); }
        }
    }
}
