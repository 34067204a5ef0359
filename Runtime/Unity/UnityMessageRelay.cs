#nullable enable
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Lives on a shadow entity and forwards its physics messages to the GameObject as
    /// OnFulcrumCollisionEnter/Stay/Exit(F.Collision), OnFulcrumTriggerEnter/Stay/Exit(F.Collider)
    /// and OnFulcrumJointBreak(float) (Unity's own OnCollisionEnter takes a UnityEngine.Collision,
    /// so the names differ). The Collision object is reused: copy what you keep.
    /// </summary>
    public sealed class UnityMessageRelay : F.Behaviour
    {
        /// <summary>The GameObject that receives the messages.</summary>
        public GameObject? Target;

        void Send(string message, object argument)
        {
            if (Target != null) Target.SendMessage(message, argument, SendMessageOptions.DontRequireReceiver);
        }

        /// <inheritdoc/>
        protected override void OnCollisionEnter(F.Collision c) => Send("OnFulcrumCollisionEnter", c);
        /// <inheritdoc/>
        protected override void OnCollisionStay(F.Collision c) => Send("OnFulcrumCollisionStay", c);
        /// <inheritdoc/>
        protected override void OnCollisionExit(F.Collision c) => Send("OnFulcrumCollisionExit", c);
        /// <inheritdoc/>
        protected override void OnTriggerEnter(F.Collider other) => Send("OnFulcrumTriggerEnter", other);
        /// <inheritdoc/>
        protected override void OnTriggerStay(F.Collider other) => Send("OnFulcrumTriggerStay", other);
        /// <inheritdoc/>
        protected override void OnTriggerExit(F.Collider other) => Send("OnFulcrumTriggerExit", other);
        /// <inheritdoc/>
        protected override void OnJointBreak(float breakForce) => Send("OnFulcrumJointBreak", breakForce);
    }
}
