using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Components
{
    /// <summary>Messages driven by the world's own contact events (narrow phase and event stage).</summary>
    public class WorldEventTests
    {
        const float Dt = 1f / 64f;

        [Test]
        public void A_ball_falling_through_a_trigger_gets_Enter_Stay_Exit_once_and_stays_in_free_fall()
        {
            var scene = new PhysicsScene(WorldSettings.Default, Dt);
            Entity zone = scene.CreateEntity("Zone");
            var box = zone.AddComponent<BoxCollider>();
            box.size = new Vector3(4, 1, 4);
            box.isTrigger = true;
            var zoneLog = zone.AddComponent<Recorder>();
            Entity ball = scene.CreateEntity("Ball", new Vector3(0, 2, 0));
            var rb = ball.AddComponent<Rigidbody>();
            ball.AddComponent<SphereCollider>().radius = 0.25f;
            var ballLog = ball.AddComponent<Recorder>();

            int steps = 64; // 1 s: from y = 2 to y = 2 - g/2 (plus the semi-implicit step's share) ~ -2.9
            for (int k = 0; k < steps; k++) scene.Tick(Dt);

            List<string> triggers = ballLog.Log.FindAll(m => m.StartsWith("OnTrigger"));
            Assert.That(triggers[0], Is.EqualTo("OnTriggerEnter"));
            Assert.That(triggers.FindAll(m => m == "OnTriggerEnter").Count, Is.EqualTo(1));
            Assert.That(triggers.FindAll(m => m == "OnTriggerExit").Count, Is.EqualTo(1));
            Assert.That(triggers[triggers.Count - 1], Is.EqualTo("OnTriggerExit"));
            Assert.That(triggers.Count, Is.GreaterThan(3), "Stay while inside");
            Assert.That(zoneLog.Log.FindAll(m => m.StartsWith("OnTrigger")), Is.EqualTo(triggers), "the zone hears the same");
            Assert.That(ballLog.Log.FindAll(m => m.StartsWith("OnCollision")), Is.Empty);

            // No physical response: exactly the semi-implicit Euler free fall v_n = -g n dt.
            Assert.That(rb.linearVelocity.Y, Is.EqualTo(-9.81f * steps * Dt).Within(1e-4f));
        }

        [Test]
        public void Collision_messages_from_the_world_carry_the_manifold_points()
        {
            var scene = new PhysicsScene(WorldSettings.Default, Dt);
            Entity ground = scene.CreateEntity("Ground", new Vector3(0, -0.5f, 0));
            ground.AddComponent<BoxCollider>().size = new Vector3(10, 1, 10);
            Entity crate = scene.CreateEntity("Crate", new Vector3(0, 0.6f, 0));
            crate.AddComponent<Rigidbody>();
            crate.AddComponent<BoxCollider>();
            var capture = crate.AddComponent<FirstCollision>();
            for (int k = 0; k < 16 && capture.Points == 0; k++) scene.Tick(Dt);
            Assert.That(capture.Points, Is.EqualTo(4), "a box face on a box face: four points");
            Assert.That(capture.Normal.Y, Is.EqualTo(1f).Within(1e-5f), "from the ground towards the crate");
            Assert.That(capture.Other, Is.EqualTo("Ground"));
            Assert.That(capture.MaxSeparation, Is.LessThan(0.05f));
        }

        public class FirstCollision : Behaviour
        {
            public int Points;
            public Vector3 Normal;
            public string Other = "";
            public float MaxSeparation = float.NegativeInfinity;

            protected override void OnCollisionEnter(Fulcrum.Components.Collision c)
            {
                Points = c.contactCount;
                Normal = c.GetContact(0).normal;
                Other = c.entity.name;
                for (int i = 0; i < c.contactCount; i++) MaxSeparation = System.MathF.Max(MaxSeparation, c.GetContact(i).separation);
            }
        }

        [Test]
        public void A_ball_that_falls_bounces_and_rests_gets_Enter_once_per_landing_Stay_while_touching_and_Exit_on_each_bounce()
        {
            var scene = new PhysicsScene(WorldSettings.Default, 1f / 60f);
            var bouncy = new PhysicsMaterial("bouncy") { bounciness = 0.7f, bounceCombine = CombineMode.Maximum };
            Entity ground = scene.CreateEntity("Ground", new Vector3(0, -0.5f, 0));
            ground.AddComponent<BoxCollider>().size = new Vector3(10, 1, 10);
            Entity ball = scene.CreateEntity("Ball", new Vector3(0, 2, 0));
            var rb = ball.AddComponent<Rigidbody>();
            var sphere = ball.AddComponent<SphereCollider>();
            sphere.radius = 0.25f;
            sphere.sharedMaterial = bouncy;
            var log = ball.AddComponent<Recorder>();
            for (int k = 0; k < 300; k++) scene.Tick(1f / 60f); // 5 s

            List<string> m = log.Log.FindAll(x => x.StartsWith("OnCollision"));
            int enters = m.FindAll(x => x == "OnCollisionEnter").Count;
            int exits = m.FindAll(x => x == "OnCollisionExit").Count;
            Assert.That(exits, Is.GreaterThanOrEqualTo(2), "it bounced at least twice");
            Assert.That(enters, Is.EqualTo(exits + 1), "every landing but the last ends in a bounce");
            // Enter, Stay*, Exit alternate strictly: no Stay or Exit without a contact, no double Enter.
            bool touching = false;
            foreach (string x in m)
            {
                if (x == "OnCollisionEnter") { Assert.That(touching, Is.False, "Enter while touching"); touching = true; }
                else Assert.That(touching, Is.True, x + " without a contact");
                if (x == "OnCollisionExit") touching = false;
            }
            Assert.That(touching, Is.True, "at rest on the ground");
            Assert.That(m[m.Count - 1], Is.EqualTo("OnCollisionStay"));
            Assert.That(rb.position.Y, Is.EqualTo(0.25f).Within(0.01f));
            Assert.That(rb.linearVelocity.Length(), Is.LessThan(0.05f));
        }
    }
}
