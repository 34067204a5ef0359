using System.Collections.Generic;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Components
{
    /// <summary>
    /// Dispatch of contact events to behaviours, driven by injected events (the same path the
    /// world's own events take after each step).
    /// </summary>
    public class MessageDispatchTests
    {
        const float Dt = 0.25f;

        sealed class Rig
        {
            public PhysicsScene Scene = null!;
            public BoxCollider Ground = null!;
            public SphereCollider Ball = null!;
            public Recorder BallLog = null!;
            public Recorder GroundLog = null!;
        }

        static Rig Build()
        {
            var r = new Rig();
            WorldSettings s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            r.Scene = new PhysicsScene(s, Dt);
            Entity ground = r.Scene.CreateEntity("Ground");
            r.Ground = ground.AddComponent<BoxCollider>();
            r.GroundLog = ground.AddComponent<Recorder>();
            // Far apart: only injected events reach them.
            Entity ball = r.Scene.CreateEntity("Ball", new Vector3(0, 10, 0));
            ball.AddComponent<Rigidbody>();
            r.Ball = ball.AddComponent<SphereCollider>();
            r.BallLog = ball.AddComponent<Recorder>();
            r.Scene.Tick(Dt);
            r.BallLog.Log.Clear();
            r.GroundLog.Log.Clear();
            return r;
        }

        static ContactEvent Event(Rig r, ContactEventKind kind, bool sensor = false) => new ContactEvent
        {
            Kind = kind,
            IsSensor = sensor,
            ShapeA = r.Ground.shape,
            ShapeB = r.Ball.shape,
            BodyA = r.Scene.world.GetShapeBody(r.Ground.shape),
            BodyB = r.Scene.world.GetShapeBody(r.Ball.shape),
            Normal = kind == ContactEventKind.End || sensor ? Vector3.Zero : Vector3.UnitY,
            Point = new Vector3(0, 0.5f, 0),
            PointCount = kind == ContactEventKind.End || sensor ? 0 : 1,
            NormalImpulse = kind == ContactEventKind.Begin ? 3f : 0.5f,
            RelativeVelocity = new Vector3(0, -2, 0),
        };

        static List<string> Messages(Recorder r) => r.Log.FindAll(m => m.StartsWith("OnCollision") || m.StartsWith("OnTrigger"));

        [Test]
        public void A_bouncing_ball_gets_Enter_once_per_landing_Stay_while_touching_and_Exit_on_each_bounce()
        {
            Rig r = Build();
            ContactEventKind[] sequence =
            {
                ContactEventKind.Begin, ContactEventKind.End,                                   // first bounce
                ContactEventKind.Begin, ContactEventKind.End,                                   // second bounce
                ContactEventKind.Begin, ContactEventKind.Persist, ContactEventKind.Persist,     // comes to rest
            };
            foreach (ContactEventKind k in sequence)
            {
                r.Scene.InjectContactEvent(Event(r, k));
                r.Scene.Tick(Dt);
            }
            string[] expected =
            {
                "OnCollisionEnter", "OnCollisionExit", "OnCollisionEnter", "OnCollisionExit",
                "OnCollisionEnter", "OnCollisionStay", "OnCollisionStay",
            };
            Assert.That(Messages(r.BallLog), Is.EqualTo(expected));
            Assert.That(Messages(r.GroundLog), Is.EqualTo(expected), "both sides hear it");
        }

        [Test]
        public void Collision_seen_from_each_side_has_normal_towards_itself_and_the_impulse_it_received()
        {
            Rig r = Build();
            var ball = r.Ball.entity.AddComponent<CollisionCapture>();
            var ground = r.Ground.entity.AddComponent<CollisionCapture>();
            r.Scene.InjectContactEvent(Event(r, ContactEventKind.Begin));
            r.Scene.Tick(Dt);

            Assert.That(ball.Other, Is.SameAs(r.Ground));
            Assert.That(ball.Normal, Is.EqualTo(Vector3.UnitY), "from the ground towards the ball, as in Unity");
            Assert.That(ball.Impulse, Is.EqualTo(new Vector3(0, 3, 0)));
            Assert.That(ball.RelativeVelocity, Is.EqualTo(new Vector3(0, 2, 0)), "ground relative to the falling ball: up");
            Assert.That(ball.Rigidbody, Is.Null, "the ground has no rigidbody");
            Assert.That(ball.Count, Is.EqualTo(1));

            Assert.That(ground.Other, Is.SameAs(r.Ball));
            Assert.That(ground.Normal, Is.EqualTo(-Vector3.UnitY));
            Assert.That(ground.Impulse, Is.EqualTo(new Vector3(0, -3, 0)));
            Assert.That(ground.RelativeVelocity, Is.EqualTo(new Vector3(0, -2, 0)));
            Assert.That(ground.Rigidbody, Is.SameAs(r.Ball.attachedRigidbody));
        }

        public class CollisionCapture : Behaviour
        {
            public Collider? Other;
            public Rigidbody? Rigidbody;
            public Vector3 Normal, Impulse, RelativeVelocity;
            public int Count;

            protected override void OnCollisionEnter(Fulcrum.Components.Collision c)
            {
                Other = c.collider;
                Rigidbody = c.rigidbody;
                Normal = c.GetContact(0).normal;
                Impulse = c.impulse;
                RelativeVelocity = c.relativeVelocity;
                Count = c.contactCount;
            }
        }

        [Test]
        public void Trigger_events_send_trigger_messages_and_no_collision_messages()
        {
            Rig r = Build();
            r.Ground.isTrigger = true;
            Assert.That(r.Scene.world.Shapes.IsSensor[r.Ground.shape.Index], Is.True, "a trigger is a sensor shape: no physical response");
            r.Scene.InjectContactEvent(Event(r, ContactEventKind.Begin, sensor: true));
            r.Scene.Tick(Dt);
            r.Scene.InjectContactEvent(Event(r, ContactEventKind.Persist, sensor: true));
            r.Scene.Tick(Dt);
            r.Scene.InjectContactEvent(Event(r, ContactEventKind.End, sensor: true));
            r.Scene.Tick(Dt);
            Assert.That(Messages(r.BallLog), Is.EqualTo(new[] { "OnTriggerEnter", "OnTriggerStay", "OnTriggerExit" }));
            Assert.That(Messages(r.GroundLog), Is.EqualTo(new[] { "OnTriggerEnter", "OnTriggerStay", "OnTriggerExit" }));
        }

        [Test]
        public void Messages_reach_the_rigidbody_entity_of_a_child_collider_and_disabled_behaviours()
        {
            Rig r = Build();
            Entity arm = r.Scene.CreateEntity("Arm", new Vector3(1, 10, 0), parent: r.Ball.entity);
            var armBox = arm.AddComponent<BoxCollider>();
            var armLog = arm.AddComponent<Recorder>();
            r.BallLog.enabled = false;
            r.BallLog.Log.Clear();
            var e = Event(r, ContactEventKind.Begin);
            e.ShapeB = armBox.shape;
            r.Scene.InjectContactEvent(e);
            r.Scene.Tick(Dt);
            Assert.That(Messages(armLog), Is.EqualTo(new[] { "OnCollisionEnter" }));
            Assert.That(Messages(r.BallLog), Is.EqualTo(new[] { "OnCollisionEnter" }), "the rigidbody's entity hears it too, even disabled");
        }

        [Test]
        public void Destroy_inside_OnCollisionEnter_is_deferred_and_the_other_side_still_hears_the_message()
        {
            Rig r = Build();
            r.Ground.entity.AddComponent<DestroyOtherOnEnter>();
            ContactEvent end = Event(r, ContactEventKind.End);
            r.Scene.InjectContactEvent(Event(r, ContactEventKind.Begin));
            r.Scene.Tick(Dt);
            Assert.That(Messages(r.BallLog), Is.EqualTo(new[] { "OnCollisionEnter" }));
            Assert.That(r.Ball.entity.isDestroyed, Is.True, "gone at the end of the frame");
            Assert.That(r.BallLog.Log, Does.Contain("OnDestroy"));
            Assert.That(r.Scene.world.BodyCount, Is.EqualTo(1), "only the ground's static body is left");

            // An end event for the removed shape still names the destroyed collider for the survivor.
            r.GroundLog.Log.Clear();
            r.Scene.InjectContactEvent(end);
            r.Scene.Tick(Dt);
            Assert.That(Messages(r.GroundLog), Is.EqualTo(new[] { "OnCollisionExit" }));
        }

        public class DestroyOtherOnEnter : Behaviour
        {
            protected override void OnCollisionEnter(Fulcrum.Components.Collision c) => scene.Destroy(c.entity);
        }

        [Test]
        public void Dispatch_allocates_nothing_once_warm()
        {
            Rig r = Build();
            ContactEvent persist = Event(r, ContactEventKind.Persist);
            r.BallLog.Log.Capacity = 1 << 16;
            r.GroundLog.Log.Capacity = 1 << 16;
            long bytes = AllocationProbe.SteadyStateBytes(() => { r.Scene.InjectContactEvent(persist); r.Scene.Tick(Dt); });
            Assert.That(bytes, Is.EqualTo(0));
        }
    }
}
