using System;
using System.Numerics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Validation
{
    /// <summary>Handles carry their world's id: another world refuses them instead of touching its own object in the same slot.</summary>
    public class ForeignHandleTests
    {
        static BodyHandle Ball(World world, Vector3 at)
        {
            BodyHandle b = world.CreateBody(BodyDef.Dynamic(at));
            world.AddShape(b, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            return b;
        }

        [Test]
        public void A_body_handle_from_another_world_is_refused_and_changes_nothing()
        {
            var a = new World();
            var b = new World();
            BodyHandle fromA = Ball(a, Vector3.Zero);
            BodyHandle inB = Ball(b, new Vector3(0, 5, 0)); // same slot and generation as fromA
            Assert.That(fromA.Index, Is.EqualTo(inB.Index));
            Assert.That(fromA.Generation, Is.EqualTo(inB.Generation));
            Assert.That(fromA.WorldId, Is.Not.EqualTo(inB.WorldId));

            Assert.That(b.IsValid(fromA), Is.False);
            Assert.That(() => b.DestroyBody(fromA), Throws.TypeOf<StaleHandleException>().With.Message.Contains("World " + a.Id));
            Assert.That(() => b.AddForce(fromA, new Vector3(0, 100, 0), ForceMode.VelocityChange), Throws.TypeOf<StaleHandleException>());
            Assert.That(() => b.GetBody(fromA), Throws.TypeOf<StaleHandleException>());
            Assert.That(() => b.AddShape(fromA, ShapeDef.Of(ShapeGeometry.Sphere(1))), Throws.TypeOf<StaleHandleException>());
            Assert.That(() => b.CreateJoint(JointDef.Ball(fromA, BodyHandle.None, Vector3.Zero, Vector3.Zero)), Throws.TypeOf<StaleHandleException>());

            Assert.That(b.IsValid(inB), Is.True);
            Assert.That(b.GetBody(inB).LinearVelocity, Is.EqualTo(Vector3.Zero));
            Assert.That(b.BodyCount, Is.EqualTo(1));
        }

        [Test]
        public void Shape_and_joint_handles_from_another_world_are_refused()
        {
            var a = new World();
            var b = new World();
            BodyHandle ba = Ball(a, Vector3.Zero);
            BodyHandle bb = Ball(b, Vector3.Zero);
            JointHandle ja = a.CreateJoint(JointDef.Ball(ba, BodyHandle.None, Vector3.Zero, Vector3.Zero));
            JointHandle jb = b.CreateJoint(JointDef.Ball(bb, BodyHandle.None, Vector3.Zero, Vector3.Zero));
            Span<ShapeHandle> shapes = stackalloc ShapeHandle[1];
            a.GetShapes(ba, shapes);
            ShapeHandle sa = shapes[0];

            Assert.That(b.IsValid(sa), Is.False);
            Assert.That(() => b.RemoveShape(sa), Throws.TypeOf<StaleHandleException>());
            Assert.That(b.IsValid(ja), Is.False);
            Assert.That(() => b.DestroyJoint(ja), Throws.TypeOf<StaleHandleException>());
            Assert.That(b.IsValid(jb), Is.True);
            Assert.That(a.IsValid(sa) && a.IsValid(ja), Is.True);
        }

        [Test]
        public void A_soft_body_handle_from_another_world_is_refused()
        {
            var a = new World();
            var b = new World();
            SoftBodyDef def = SoftBodyDef.Of(SoftMesh.Box(Vector3.One, 1, 1, 1), MaterialPresets.Jelly, new Vector3(0, 2, 0));
            SoftBodyHandle ha = a.CreateSoftBody(def);
            SoftBodyHandle hb = b.CreateSoftBody(def);
            Assert.That(b.IsValid(ha), Is.False);
            Assert.That(() => b.DestroySoftBody(ha), Throws.TypeOf<StaleHandleException>().With.Message.Contains("World " + a.Id));
            Assert.That(b.IsValid(hb), Is.True);
        }

        [Test]
        public void Handles_returned_by_queries_and_events_carry_the_world()
        {
            var w = new World();
            BodyHandle ball = Ball(w, Vector3.Zero);
            Assert.That(w.GetBody(ball).Handle.WorldId, Is.EqualTo(w.Id));
            Span<BodyHandle> all = stackalloc BodyHandle[1];
            w.GetBodies(all);
            Assert.That(all[0], Is.EqualTo(ball));
            Assert.That(() => w.GetBody(new BodyHandle(ball.Index, ball.Generation)), Throws.TypeOf<StaleHandleException>().With.Message.Contains("no world id"));
            Assert.That(default(BodyHandle).IsNone, Is.True);
        }

        [Test]
        public void A_proxy_handle_from_another_bridge_is_refused_and_bridge_inputs_are_limited()
        {
            using var one = new Fulcrum.Components.PhysicsBridge();
            using var two = new Fulcrum.Components.PhysicsBridge();
            var a = new Fulcrum.Tests.Components.PhysicsBridgeTests.Thing("a", System.Numerics.Vector3.Zero);
            var b = new Fulcrum.Tests.Components.PhysicsBridgeTests.Thing("b", System.Numerics.Vector3.Zero);
            Fulcrum.Components.ProxyHandle pa = one.Register(a, BodyDef.Default, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            Fulcrum.Components.ProxyHandle pb = two.Register(b, BodyDef.Default, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            Assert.That(pa.Index, Is.EqualTo(pb.Index));
            Assert.That(two.IsRegistered(pa), Is.False);
            Assert.That(() => two.Unregister(pa), Throws.TypeOf<StaleHandleException>().With.Message.Contains("another").Or.Message.Contains("not this one"));
            Assert.That(() => two.AddForce(pa, System.Numerics.Vector3.One), Throws.TypeOf<StaleHandleException>());
            Assert.That(two.IsRegistered(pb), Is.True);
            Assert.That(() => one.AddTorque(pa, new System.Numerics.Vector3(3e38f)), Throws.ArgumentException.With.Message.Contains("Limits.MaxForce"));
            Assert.That(() => one.SetAngularVelocity(pa, new System.Numerics.Vector3(3e38f)), Throws.ArgumentException.With.Message.Contains("Limits.MaxInputSpeed"));
        }
    }
}
