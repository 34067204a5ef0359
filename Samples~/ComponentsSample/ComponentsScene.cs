using System.Numerics;
using Fulcrum;
using Fulcrum.Components;

namespace ComponentsSample
{
    /// <summary>
    /// The sample's scene: a crate lands on the ground and a ball rolls through a trigger. Built
    /// the same way by the console program (<see cref="Program"/>) and by the Unity behaviour
    /// (<c>Unity/ComponentsSampleBehaviour.cs</c>), which only differ in who calls
    /// <see cref="PhysicsScene.Tick"/>.
    /// </summary>
    public sealed class ComponentsScene
    {
        /// <summary>The headless component scene.</summary>
        public readonly PhysicsScene Scene;

        /// <summary>The 10 kg crate dropped from 3 m.</summary>
        public readonly Entity Crate;

        /// <summary>The weightless ball launched at 4 m/s through the trigger.</summary>
        public readonly Entity Ball;

        ComponentsScene(PhysicsScene scene, Entity crate, Entity ball)
        {
            Scene = scene;
            Crate = crate;
            Ball = ball;
        }

        /// <summary>Builds the scene with a fixed physics step of <paramref name="fixedDeltaTime"/> seconds.</summary>
        public static ComponentsScene Create(float fixedDeltaTime)
        {
            var scene = new PhysicsScene(WorldSettings.Default, fixedDeltaTime);

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
            return new ComponentsScene(scene, crate, ball);
        }
    }
}
