using System;
using System.Numerics;
using Fulcrum.Collision;
using Fulcrum.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Components
{
    public class BadInputTests
    {
        static PhysicsScene NewScene() => new PhysicsScene(WorldSettings.Default, 0.25f);

        [Test]
        public void Negative_mass_throws_naming_the_component_and_field_and_changes_nothing()
        {
            PhysicsScene scene = NewScene();
            var rb = scene.CreateEntity("Ball").AddComponent<Rigidbody>();
            var ex = Assert.Throws<ArgumentException>(() => rb.mass = -1f)!;
            Assert.That(ex.ParamName, Is.EqualTo("mass"));
            Assert.That(ex.Message, Does.Contain("Rigidbody on 'Ball'"));
            Assert.That(rb.mass, Is.EqualTo(1f));
            Assert.That(scene.world.GetBody(rb.body).Mass, Is.EqualTo(1f));
        }

        [Test]
        public void Zero_size_box_throws_naming_the_component_and_field_and_keeps_the_old_shape()
        {
            PhysicsScene scene = NewScene();
            var box = scene.CreateEntity("Crate").AddComponent<BoxCollider>();
            ShapeHandle before = box.shape;
            var ex = Assert.Throws<ArgumentException>(() => box.size = new Vector3(0, 1, 1))!;
            Assert.That(ex.ParamName, Is.EqualTo("size"));
            Assert.That(ex.Message, Does.Contain("BoxCollider on 'Crate'"));
            Assert.That(box.size, Is.EqualTo(Vector3.One));
            Assert.That(box.shape, Is.EqualTo(before));
            Assert.Throws<ArgumentException>(() => scene.CreateEntity("Pill").AddComponent<CapsuleCollider>().radius = 0f);
            Assert.Throws<ArgumentException>(() => scene.CreateEntity("Orb").AddComponent<SphereCollider>().radius = float.NaN);
        }

        [Test]
        public void A_second_rigidbody_on_one_entity_is_refused_and_not_kept()
        {
            PhysicsScene scene = NewScene();
            Entity e = scene.CreateEntity("Cart");
            e.AddComponent<Rigidbody>();
            var ex = Assert.Throws<InvalidOperationException>(() => e.AddComponent<Rigidbody>())!;
            Assert.That(ex.Message, Does.Contain("'Cart' already has a Rigidbody"));
            Assert.That(scene.world.BodyCount, Is.EqualTo(1));
            var list = new System.Collections.Generic.List<Rigidbody>();
            Assert.That(e.GetComponents(list), Is.EqualTo(1));
        }

        [Test]
        public void A_non_convex_mesh_collider_on_a_rigidbody_conflicts_with_its_convex_colliders()
        {
            PhysicsScene scene = NewScene();
            Entity car = scene.CreateEntity("Car");
            car.AddComponent<Rigidbody>();
            car.AddComponent<BoxCollider>();
            Entity body = scene.CreateEntity("Shell", parent: car);
            var mesh = body.AddComponent<Fulcrum.Components.MeshCollider>();
            var tetra = new Mesh(new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ }, new[] { 0, 1, 2, 0, 1, 3, 0, 2, 3, 1, 2, 3 });
            var ex = Assert.Throws<InvalidOperationException>(() => mesh.sharedMesh = tetra)!;
            Assert.That(ex.Message, Does.Contain("MeshCollider on 'Shell'").And.Contain("convex = false"));
            Assert.That(mesh.sharedMesh, Is.Null, "nothing changed");
        }

        [Test]
        public void Mesh_with_an_index_out_of_range_throws_naming_the_index()
        {
            var ex = Assert.Throws<ArgumentException>(() => new Mesh(new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitY }, new[] { 0, 1, 3 }))!;
            Assert.That(ex.Message, Does.Contain("triangles[2] = 3"));
        }

        [Test]
        public void Component_setters_inside_World_Step_throw_naming_the_component_and_field()
        {
            PhysicsScene scene = NewScene();
            var rb = scene.CreateEntity("Ball").AddComponent<Rigidbody>();
            var stage = new MeddlingStage(rb);
            scene.world.SoftBodyStage = stage;
            scene.Tick(0.25f);
            Assert.That(stage.Caught, Is.Not.Null);
            Assert.That(stage.Caught!.Message, Does.Contain("Rigidbody on 'Ball': mass cannot be changed while the world steps"));
            Assert.That(rb.mass, Is.EqualTo(1f));
            Assert.That(scene.world.IsStepping, Is.False);
        }

        // A Core callback that runs inside World.Step and tries to change a component.
        sealed class MeddlingStage : ISoftBodyStage
        {
            readonly Rigidbody _rb;
            public InvalidOperationException? Caught;
            public MeddlingStage(Rigidbody rb) => _rb = rb;
            public bool HasWork => true;
            public void Step(World world, float dt)
            {
                try { _rb.mass = 5f; }
                catch (InvalidOperationException e) { Caught = e; }
            }
        }

        [Test]
        public void Stepping_the_scene_from_its_own_collision_message_throws_naming_the_message()
        {
            PhysicsScene scene = NewScene();
            var ground = scene.CreateEntity("Ground").AddComponent<BoxCollider>();
            Entity ball = scene.CreateEntity("Ball", new Vector3(0, 1, 0));
            ball.AddComponent<Rigidbody>();
            var sphere = ball.AddComponent<SphereCollider>();
            var nested = ball.AddComponent<NestedTick>();
            scene.InjectContactEvent(new ContactEvent { Kind = ContactEventKind.Begin, ShapeA = ground.shape, ShapeB = sphere.shape, PointCount = 1, Normal = Vector3.UnitY });
            scene.Tick(0.25f);
            Assert.That(nested.TickError, Does.Contain("PhysicsScene.Tick was called from OnCollisionEnter"));
            Assert.That(nested.DestroyError, Does.Contain("DestroyImmediate(Entity 'Ground') is not allowed from OnCollisionEnter"));
            Assert.That(ground.isDestroyed, Is.False);
        }

        public class NestedTick : Behaviour
        {
            public string TickError = "", DestroyError = "";
            protected override void OnCollisionEnter(Fulcrum.Components.Collision c)
            {
                try { scene.Tick(0.25f); } catch (InvalidOperationException e) { TickError = e.Message; }
                try { scene.DestroyImmediate(c.entity); } catch (InvalidOperationException e) { DestroyError = e.Message; }
            }
        }

        [Test]
        public void Parenting_an_entity_under_its_own_child_throws()
        {
            PhysicsScene scene = NewScene();
            Entity a = scene.CreateEntity("A");
            Entity b = scene.CreateEntity("B", parent: a);
            var ex = Assert.Throws<ArgumentException>(() => a.transform.parent = b.transform)!;
            Assert.That(ex.Message, Does.Contain("loop"));
            Assert.That(a.transform.parent, Is.Null);
        }

        [Test]
        public void Non_finite_transform_and_force_values_are_refused()
        {
            PhysicsScene scene = NewScene();
            Entity e = scene.CreateEntity("Probe");
            var rb = e.AddComponent<Rigidbody>();
            Assert.Throws<ArgumentException>(() => e.transform.position = new Vector3(float.NaN, 0, 0));
            Assert.Throws<ArgumentException>(() => rb.AddForce(new Vector3(float.PositiveInfinity, 0, 0)));
            Assert.Throws<ArgumentException>(() => scene.Tick(-1f));
            Assert.That(rb.linearVelocity, Is.EqualTo(Vector3.Zero));
        }
    }
}
