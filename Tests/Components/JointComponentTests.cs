using System;
using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Components
{
    public class JointComponentTests
    {
        const float Dt = 1f / 60f;

        static Rigidbody Body(PhysicsScene scene, string name, Vector3 at, float mass = 1f)
        {
            Entity e = scene.CreateEntity(name, at);
            var rb = e.AddComponent<Rigidbody>();
            rb.mass = mass;
            e.AddComponent<SphereCollider>().radius = 0.2f;
            return rb;
        }

        public class BreakCounter : Behaviour
        {
            public int Count;
            public float Force;
            protected override void OnJointBreak(float breakForce) { Count++; Force = breakForce; }
        }

        [Test]
        public void A_joint_holds_below_its_break_force_then_breaks_once_over_it_and_the_body_falls_free()
        {
            var scene = new PhysicsScene(WorldSettings.Default, Dt);
            Rigidbody ball = Body(scene, "Ball", new Vector3(0, 2, 0));
            var joint = ball.entity.AddComponent<FixedJoint>();
            joint.breakForce = 20f;                       // weight is 9.81 N
            var counter = ball.entity.AddComponent<BreakCounter>();
            for (int k = 0; k < 30; k++) scene.Tick(Dt);
            Assert.That(counter.Count, Is.EqualTo(0));
            Assert.That(ball.position.Y, Is.EqualTo(2f).Within(0.01f), "held");
            Assert.That(joint.currentForce.Y, Is.EqualTo(9.81f).Within(0.5f), "the joint carries the weight");

            for (int k = 0; k < 10; k++)
            {
                ball.AddForce(new Vector3(0, -30f, 0));
                scene.Tick(Dt);
            }
            Assert.That(counter.Count, Is.EqualTo(1), "OnJointBreak once");
            Assert.That(counter.Force, Is.GreaterThan(20f));
            Assert.That(joint.isDestroyed, Is.True, "the joint component goes at the end of the frame, as in Unity");
            Assert.That(scene.world.JointCount, Is.EqualTo(0));
            Assert.That(ball.position.Y, Is.LessThan(1.99f), "falls once free");
        }

        [Test]
        public void A_hinge_motor_turns_the_door_at_its_target_speed_until_the_limit()
        {
            WorldSettings s = WorldSettings.Default;
            s.Gravity = Vector3.Zero;
            var scene = new PhysicsScene(s, Dt);
            Entity door = scene.CreateEntity("Door", new Vector3(0.5f, 0, 0));
            var rb = door.AddComponent<Rigidbody>();
            rb.angularDamping = 0;
            door.AddComponent<BoxCollider>().size = new Vector3(1, 2, 0.1f);
            var hinge = door.AddComponent<HingeJoint>();
            hinge.anchor = new Vector3(-0.5f, 0, 0);
            hinge.axis = Vector3.UnitY;
            hinge.useMotor = true;
            hinge.motor = new JointMotor { targetVelocity = 90f, force = 100f };
            hinge.useLimits = true;
            hinge.limits = new JointLimits { min = -10f, max = 60f };
            for (int k = 0; k < 30; k++) scene.Tick(Dt); // 0.5 s at 90 deg/s: 45 degrees
            Assert.That(hinge.angle, Is.EqualTo(45f).Within(2f));
            Vector3 hingePoint = door.transform.TransformPoint(hinge.anchor);
            Assert.That(Vector3.Distance(hingePoint, Vector3.Zero), Is.LessThan(0.01f), "the hinge point stays put");
            for (int k = 0; k < 60; k++) scene.Tick(Dt);
            Assert.That(hinge.angle, Is.EqualTo(60f).Within(2f), "stopped by the upper limit");
        }

        [Test]
        public void A_distance_joint_to_another_body_keeps_their_distance()
        {
            var scene = new PhysicsScene(WorldSettings.Default, Dt);
            Rigidbody anchorBody = Body(scene, "Hook", new Vector3(0, 5, 0), 1f);
            anchorBody.isKinematic = true;
            Rigidbody bob = Body(scene, "Bob", new Vector3(1, 5, 0));
            var rope = bob.entity.AddComponent<DistanceJoint>();
            rope.connectedBody = anchorBody;
            rope.connectedAnchor = Vector3.Zero; // the hook's centre: a 1 m rod (auto-configured anchors would start together)
            float lowest = float.MaxValue, worstLength = 0;
            for (int k = 0; k < 60; k++)
            {
                scene.Tick(Dt);
                lowest = MathF.Min(lowest, bob.position.Y);
                worstLength = MathF.Max(worstLength, MathF.Abs(Vector3.Distance(bob.position, anchorBody.position) - 1f));
            }
            Assert.That(worstLength, Is.LessThan(0.02f), "the rod keeps its 1 m");
            Assert.That(lowest, Is.EqualTo(4f).Within(0.03f), "it swung through the bottom, 1 m below the hook");
            Assert.That(bob.position.X, Is.LessThan(-0.5f), "and up the other side");
        }

        [Test]
        public void A_joint_to_a_destroyed_body_or_without_a_rigidbody_throws_naming_the_component()
        {
            var scene = new PhysicsScene(WorldSettings.Default, Dt);
            Rigidbody frame = Body(scene, "Frame", Vector3.Zero);
            Rigidbody door = Body(scene, "Door", new Vector3(1, 0, 0));
            var hinge = door.entity.AddComponent<HingeJoint>();
            scene.DestroyImmediate(frame.entity);
            var ex = Assert.Throws<InvalidOperationException>(() => hinge.connectedBody = frame)!;
            Assert.That(ex.Message, Does.Contain("HingeJoint on 'Door': connectedBody (Rigidbody on 'Frame') has been destroyed"));
            Assert.That(hinge.connectedBody, Is.Null);

            Entity bare = scene.CreateEntity("Bare");
            ex = Assert.Throws<InvalidOperationException>(() => bare.AddComponent<FixedJoint>())!;
            Assert.That(ex.Message, Does.Contain("FixedJoint on 'Bare' needs a Rigidbody"));

            var arg = Assert.Throws<ArgumentException>(() => hinge.limits = new JointLimits { min = 30, max = 10 })!;
            Assert.That(arg.ParamName, Is.EqualTo("limits"));
            Assert.Throws<ArgumentException>(() => hinge.breakForce = -1f);
        }
    }
}
