#nullable enable
using System.Collections.Generic;
using UnityEngine;
using F = Fulcrum.Components;

namespace Fulcrum.Unity
{
    /// <summary>
    /// Lives on a shadow entity and hands its physics messages to the GameObject's
    /// MonoBehaviours that implement <see cref="IFulcrumCollisionHandler"/>,
    /// <see cref="IFulcrumTriggerHandler"/> or <see cref="IFulcrumJointBreakHandler"/>: a direct
    /// interface call per receiver, found with GetComponents into a reused list (no SendMessage
    /// reflection, no allocation per contact per step). Unity's own OnCollisionEnter takes a
    /// UnityEngine.Collision, so the names differ.
    /// </summary>
    public sealed class UnityMessageRelay : F.Behaviour
    {
        /// <summary>The GameObject that receives the messages.</summary>
        public GameObject? Target;

        readonly List<IFulcrumCollisionHandler> _collision = new List<IFulcrumCollisionHandler>();
        readonly List<IFulcrumTriggerHandler> _trigger = new List<IFulcrumTriggerHandler>();
        readonly List<IFulcrumJointBreakHandler> _jointBreak = new List<IFulcrumJointBreakHandler>();

        // The target's receivers of one kind, into a reused list (GetComponents(List) does not allocate).
        List<T> Handlers<T>(List<T> list)
        {
            list.Clear();
            if (Target != null) Target.GetComponents(list);
            return list;
        }

        /// <inheritdoc/>
        protected override void OnCollisionEnter(F.Collision c)
        {
            List<IFulcrumCollisionHandler> h = Handlers(_collision);
            for (int i = 0; i < h.Count; i++) h[i].OnFulcrumCollisionEnter(c);
        }

        /// <inheritdoc/>
        protected override void OnCollisionStay(F.Collision c)
        {
            List<IFulcrumCollisionHandler> h = Handlers(_collision);
            for (int i = 0; i < h.Count; i++) h[i].OnFulcrumCollisionStay(c);
        }

        /// <inheritdoc/>
        protected override void OnCollisionExit(F.Collision c)
        {
            List<IFulcrumCollisionHandler> h = Handlers(_collision);
            for (int i = 0; i < h.Count; i++) h[i].OnFulcrumCollisionExit(c);
        }

        /// <inheritdoc/>
        protected override void OnTriggerEnter(F.Collider other)
        {
            List<IFulcrumTriggerHandler> h = Handlers(_trigger);
            for (int i = 0; i < h.Count; i++) h[i].OnFulcrumTriggerEnter(other);
        }

        /// <inheritdoc/>
        protected override void OnTriggerStay(F.Collider other)
        {
            List<IFulcrumTriggerHandler> h = Handlers(_trigger);
            for (int i = 0; i < h.Count; i++) h[i].OnFulcrumTriggerStay(other);
        }

        /// <inheritdoc/>
        protected override void OnTriggerExit(F.Collider other)
        {
            List<IFulcrumTriggerHandler> h = Handlers(_trigger);
            for (int i = 0; i < h.Count; i++) h[i].OnFulcrumTriggerExit(other);
        }

        /// <inheritdoc/>
        protected override void OnJointBreak(float breakForce)
        {
            List<IFulcrumJointBreakHandler> h = Handlers(_jointBreak);
            for (int i = 0; i < h.Count; i++) h[i].OnFulcrumJointBreak(breakForce);
        }
    }
}
