#nullable enable
using System;
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

        // Hands one message to each receiver of its kind. The lambdas passed in capture nothing
        // (static), so the compiler caches them: no delegate is allocated per message.
        void Relay<THandler, TMessage>(List<THandler> list, TMessage message, Action<THandler, TMessage> deliver)
        {
            List<THandler> h = Handlers(list);
            for (int i = 0; i < h.Count; i++) deliver(h[i], message);
        }

        /// <inheritdoc/>
        protected override void OnCollisionEnter(F.Collision c) => Relay(_collision, c, static (h, m) => h.OnFulcrumCollisionEnter(m));

        /// <inheritdoc/>
        protected override void OnCollisionStay(F.Collision c) => Relay(_collision, c, static (h, m) => h.OnFulcrumCollisionStay(m));

        /// <inheritdoc/>
        protected override void OnCollisionExit(F.Collision c) => Relay(_collision, c, static (h, m) => h.OnFulcrumCollisionExit(m));

        /// <inheritdoc/>
        protected override void OnTriggerEnter(F.Collider other) => Relay(_trigger, other, static (h, m) => h.OnFulcrumTriggerEnter(m));

        /// <inheritdoc/>
        protected override void OnTriggerStay(F.Collider other) => Relay(_trigger, other, static (h, m) => h.OnFulcrumTriggerStay(m));

        /// <inheritdoc/>
        protected override void OnTriggerExit(F.Collider other) => Relay(_trigger, other, static (h, m) => h.OnFulcrumTriggerExit(m));

        /// <inheritdoc/>
        protected override void OnJointBreak(float breakForce) => Relay(_jointBreak, breakForce, static (h, m) => h.OnFulcrumJointBreak(m));
    }
}
