using UnityEngine;
using IPhysicsEntity = Fulcrum.Components.IPhysicsEntity;

namespace BridgeSample
{
    /// <summary>
    /// A Unity Transform seen by the PhysicsBridge: the bridge reads and writes its world pose.
    /// The numbers are copied component by component, so Fulcrum simulates in Unity's frame
    /// (y up, metres).
    /// </summary>
    public sealed class TransformEntity : IPhysicsEntity
    {
        readonly Transform _transform;

        /// <summary>Wraps <paramref name="transform"/>.</summary>
        public TransformEntity(Transform transform) { _transform = transform; }

        /// <summary>Reads the Transform's world position and rotation.</summary>
        public void GetPose(out System.Numerics.Vector3 position, out System.Numerics.Quaternion rotation)
        {
            Vector3 p = _transform.position;
            Quaternion q = _transform.rotation;
            position = new System.Numerics.Vector3(p.x, p.y, p.z);
            rotation = new System.Numerics.Quaternion(q.x, q.y, q.z, q.w);
        }

        /// <summary>Writes the Transform's world position and rotation.</summary>
        public void SetPose(System.Numerics.Vector3 position, System.Numerics.Quaternion rotation) =>
            _transform.SetPositionAndRotation(new Vector3(position.X, position.Y, position.Z), new Quaternion(rotation.X, rotation.Y, rotation.Z, rotation.W));

        /// <summary>The GameObject's name, for contact messages.</summary>
        public override string ToString() => _transform.name;
    }
}
