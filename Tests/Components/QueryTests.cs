using System;
using System.Numerics;
using Fulcrum.Components;
using NUnit.Framework;
using RaycastHit = Fulcrum.Components.RaycastHit;

namespace Fulcrum.Tests.Components
{
    public class ComponentQueryTests
    {
        static PhysicsScene Scene(out BoxCollider ground, out SphereCollider ball, out BoxCollider zone)
        {
            var scene = new PhysicsScene();
            Entity g = scene.CreateEntity("Ground", new Vector3(0, -0.5f, 0));
            ground = g.AddComponent<BoxCollider>();
            ground.size = new Vector3(20, 1, 20);
            Entity b = scene.CreateEntity("Ball", new Vector3(3, 1, 0));
            b.AddComponent<Rigidbody>();
            ball = b.AddComponent<SphereCollider>();
            Entity z = scene.CreateEntity("Zone", new Vector3(0, 5, 0));
            zone = z.AddComponent<BoxCollider>();
            zone.isTrigger = true;
            return scene;
        }

        [Test]
        public void Raycast_reports_the_nearest_collider_with_point_normal_and_distance()
        {
            PhysicsScene scene = Scene(out BoxCollider ground, out _, out BoxCollider zone);
            Assert.That(scene.Raycast(new Vector3(0, 10, 0), -Vector3.UnitY, out RaycastHit hit), Is.True);
            Assert.That(hit.collider, Is.SameAs(zone), "triggers are hit by default (queriesHitTriggers)");
            Assert.That(hit.distance, Is.EqualTo(4.5f).Within(1e-4f));

            Assert.That(scene.Raycast(new Vector3(0, 10, 0), -Vector3.UnitY, out hit, 100f, PhysicsScene.DefaultRaycastLayers, QueryTriggerInteraction.Ignore), Is.True);
            Assert.That(hit.collider, Is.SameAs(ground));
            Assert.That(hit.distance, Is.EqualTo(10f).Within(1e-4f));
            Assert.That(hit.normal.Y, Is.EqualTo(1f).Within(1e-5f));
            Assert.That(hit.point.Y, Is.EqualTo(0f).Within(1e-4f));
            Assert.That(hit.rigidbody, Is.Null);
            Assert.That(scene.Raycast(new Vector3(0, 10, 0), -Vector3.UnitY, out hit, 5f, PhysicsScene.DefaultRaycastLayers, QueryTriggerInteraction.Ignore), Is.False, "ground beyond maxDistance");
        }

        [Test]
        public void Layer_masks_filter_and_the_Ignore_Raycast_layer_is_skipped_by_default()
        {
            PhysicsScene scene = Scene(out BoxCollider ground, out _, out BoxCollider zone);
            zone.entity.layer = PhysicsScene.IgnoreRaycastLayer;
            ground.entity.layer = 5;
            Assert.That(scene.Raycast(new Vector3(0, 10, 0), -Vector3.UnitY, out RaycastHit hit), Is.True);
            Assert.That(hit.collider, Is.SameAs(ground), "the zone on Ignore Raycast is skipped");
            Assert.That(scene.Raycast(new Vector3(0, 10, 0), -Vector3.UnitY, out _, 100f, PhysicsScene.DefaultRaycastLayers & ~(1 << 5)), Is.False, "mask without layer 5");
            Assert.That(scene.Raycast(new Vector3(0, 10, 0), -Vector3.UnitY, out hit, 100f, 1 << PhysicsScene.IgnoreRaycastLayer), Is.True);
            Assert.That(hit.collider, Is.SameAs(zone), "asked for explicitly");
        }

        [Test]
        public void RaycastNonAlloc_lists_hits_nearest_first()
        {
            PhysicsScene scene = Scene(out BoxCollider ground, out _, out BoxCollider zone);
            Span<RaycastHit> hits = new RaycastHit[4];
            int n = scene.RaycastNonAlloc(new Vector3(0, 10, 0), -Vector3.UnitY, hits);
            Assert.That(n, Is.EqualTo(2));
            Assert.That(hits[0].collider, Is.SameAs(zone));
            Assert.That(hits[1].collider, Is.SameAs(ground));
        }

        [Test]
        public void SphereCast_distance_is_how_far_the_centre_travelled()
        {
            PhysicsScene scene = Scene(out BoxCollider ground, out _, out _);
            Assert.That(scene.SphereCast(new Vector3(-5, 10, 0), 0.5f, -Vector3.UnitY, out RaycastHit hit), Is.True);
            Assert.That(hit.collider, Is.SameAs(ground));
            Assert.That(hit.distance, Is.EqualTo(9.5f).Within(1e-3f));
            Assert.Throws<ArgumentException>(() => scene.SphereCast(Vector3.Zero, 0f, Vector3.UnitY, out _));
        }

        [Test]
        public void OverlapSphere_finds_the_colliders_it_touches_without_allocating()
        {
            PhysicsScene scene = Scene(out BoxCollider ground, out SphereCollider ball, out _);
            var results = new Collider[8];
            int n = scene.OverlapSphere(new Vector3(3, 0.2f, 0), 0.5f, results);
            Assert.That(n, Is.EqualTo(2));
            Assert.That(results, Has.Member(ground).And.Member(ball));
            var hits = new RaycastHit[8];
            long bytes = AllocationProbe.SteadyStateBytes(() =>
            {
                scene.OverlapSphere(new Vector3(3, 0.2f, 0), 0.5f, results);
                scene.RaycastNonAlloc(new Vector3(0, 10, 0), -Vector3.UnitY, hits);
                scene.Raycast(new Vector3(0, 10, 0), -Vector3.UnitY, out _);
            });
            Assert.That(bytes, Is.EqualTo(0));
        }
    }
}
