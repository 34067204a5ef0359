using System;
using Fulcrum.Components;

namespace ComponentsSample
{
    /// <summary>Prints the physics messages its entity receives.</summary>
    public sealed class Reporter : Behaviour
    {
        /// <summary>Where the messages go: the console by default; the Unity behaviour points it at <c>Debug.Log</c>.</summary>
        public static Action<string> Log = Console.WriteLine;

        protected override void Start() => Log($"{name}: Start at t = {scene.time:F3} s");

        protected override void OnCollisionEnter(Collision collision)
        {
            float speed = collision.relativeVelocity.Length();
            Log($"{name}: OnCollisionEnter with {collision.entity.name} at t = {scene.fixedTime:F3} s, {collision.contactCount} points, impact speed {speed:F2} m/s");
        }

        protected override void OnTriggerEnter(Collider other) => Log($"{name}: OnTriggerEnter {other.name} at t = {scene.fixedTime:F3} s");

        protected override void OnTriggerExit(Collider other) => Log($"{name}: OnTriggerExit {other.name} at t = {scene.fixedTime:F3} s");
    }
}
