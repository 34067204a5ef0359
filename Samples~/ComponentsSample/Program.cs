using System;
using System.Numerics;
using Fulcrum;
using Fulcrum.Components;

namespace ComponentsSample
{
    /// <summary>A crate lands on the ground and a ball rolls through a trigger: the tight (component) integration, headless.</summary>
    public static class Program
    {
        public static int Main()
        {
            var scene = new PhysicsScene(WorldSettings.Default, fixedDeltaTime: 1f / 50f);

            Entity ground = scene.CreateEntity("Ground", new Vector3(0, -0.5f, 0));
            ground.AddComponent<BoxCollider>().size = new Vector3(20, 1, 20);

            Entity crate = scene.CreateEntity("Crate", new Vector3(0, 3, 0));
            var body = crate.AddComponent<Rigidbody>();
            body.mass = 10f;
            body.interpolation = RigidbodyInterpolation.Interpolate;
            crate.AddComponent<BoxCollider>();
            crate.AddComponent<Reporter>();

            Entity gate = scene.CreateEntity("Gate", new Vector3(4, 1, 0));
            var trigger = gate.AddComponent<BoxCollider>();
            trigger.size = new Vector3(1, 2, 4);
            trigger.isTrigger = true;

            Entity ball = scene.CreateEntity("Ball", new Vector3(0, 0.5f, 2));
            var rb = ball.AddComponent<Rigidbody>();
            ball.AddComponent<SphereCollider>();
            ball.AddComponent<Reporter>();
            rb.useGravity = false;
            rb.AddForce(new Vector3(4, 0, 0), ForceMode.VelocityChange);
            ball.transform.position = new Vector3(0, 1, 0);

            // A 60 Hz render loop over a 50 Hz physics step for two simulated seconds.
            for (int frame = 0; frame < 120; frame++) scene.Tick(1f / 60f);

            Console.WriteLine($"crate at y = {crate.transform.position.Y:F3} m after {scene.fixedTime:F2} s ({scene.world.StepIndex} steps, {scene.frameCount} frames)");
            Console.WriteLine($"ball at x = {ball.transform.position.X:F3} m");
            return 0;
        }
    }

    /// <summary>Prints the physics messages its entity receives.</summary>
    public sealed class Reporter : Behaviour
    {
        protected override void Start() => Console.WriteLine($"{name}: Start at t = {scene.time:F3} s");

        protected override void OnCollisionEnter(Collision collision)
        {
            float speed = collision.relativeVelocity.Length();
            Console.WriteLine($"{name}: OnCollisionEnter with {collision.entity.name} at t = {scene.fixedTime:F3} s, {collision.contactCount} points, impact speed {speed:F2} m/s");
        }

        protected override void OnTriggerEnter(Collider other) => Console.WriteLine($"{name}: OnTriggerEnter {other.name} at t = {scene.fixedTime:F3} s");

        protected override void OnTriggerExit(Collider other) => Console.WriteLine($"{name}: OnTriggerExit {other.name} at t = {scene.fixedTime:F3} s");
    }
}
