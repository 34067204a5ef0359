#nullable enable
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Implemented by a MonoBehaviour on a GameObject with Fulcrum colliders to receive its
    /// collision messages (Unity's OnCollisionEnter/Stay/Exit). The Collision object is reused
    /// between messages: copy what you keep. Use <see cref="FulcrumWorld.FaceOf"/> for the Unity
    /// collider of <see cref="F.Collision.collider"/>.
    /// </summary>
    public interface IFulcrumCollisionHandler
    {
        /// <summary>A contact began this step.</summary>
        void OnFulcrumCollisionEnter(F.Collision collision);
        /// <summary>A contact goes on (every step while touching).</summary>
        void OnFulcrumCollisionStay(F.Collision collision);
        /// <summary>A contact ended this step.</summary>
        void OnFulcrumCollisionExit(F.Collision collision);
    }

    /// <summary>Implemented by a MonoBehaviour to receive trigger messages (Unity's OnTriggerEnter/Stay/Exit).</summary>
    public interface IFulcrumTriggerHandler
    {
        /// <summary>Another collider entered a trigger.</summary>
        void OnFulcrumTriggerEnter(F.Collider other);
        /// <summary>Another collider is still in the trigger.</summary>
        void OnFulcrumTriggerStay(F.Collider other);
        /// <summary>Another collider left the trigger.</summary>
        void OnFulcrumTriggerExit(F.Collider other);
    }

    /// <summary>Implemented by a MonoBehaviour to hear that a joint on its GameObject broke (Unity's OnJointBreak).</summary>
    public interface IFulcrumJointBreakHandler
    {
        /// <summary>A joint broke under <paramref name="breakForce"/> newtons.</summary>
        void OnFulcrumJointBreak(float breakForce);
    }
}
