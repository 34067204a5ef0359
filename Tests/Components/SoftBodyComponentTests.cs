using System;
using System.Numerics;
using Fulcrum.Components;
using Fulcrum.SoftBodies;
using NUnit.Framework;
using SoftBody = Fulcrum.Components.SoftBody;

namespace Fulcrum.Tests.Components
{
    public class SoftBodyComponentTests
    {
        [Test]
        public void A_jelly_cube_component_falls_onto_a_box_collider_and_rests_on_it()
        {
            var scene = new PhysicsScene(WorldSettings.Default, 1f / 60f);
            Entity ground = scene.CreateEntity("Ground", new Vector3(0, -0.5f, 0));
            ground.AddComponent<BoxCollider>().size = new Vector3(10, 1, 10);
            Entity jelly = scene.CreateEntity("Jelly", new Vector3(0, 1.5f, 0));
            var soft = jelly.AddComponent<SoftBody>();
            soft.material = MaterialPresets.Jelly;
            soft.mesh = SoftMesh.Box(Vector3.One, 3, 3, 3);
            Assert.That(soft.body!.TotalMass, Is.EqualTo(1030f).Within(1f), "density x 1 m^3");
            for (int k = 0; k < 120; k++) scene.Tick(1f / 60f);
            SoftBodyStats stats = soft.body.ComputeStats();
            Assert.That(stats.Centroid.Y, Is.EqualTo(0.5f).Within(0.1f), "resting on the ground, a little squashed");
            Assert.That(stats.VolumeRatio, Is.EqualTo(1f).Within(0.05f), "nearly incompressible jelly keeps its volume");
        }

        [Test]
        public void A_soft_body_and_a_rigidbody_cannot_share_an_entity()
        {
            var scene = new PhysicsScene();
            Entity e = scene.CreateEntity("Blob");
            e.AddComponent<SoftBody>();
            var ex = Assert.Throws<InvalidOperationException>(() => e.AddComponent<Rigidbody>())!;
            Assert.That(ex.Message, Does.Contain("'Blob' has a SoftBody"));
            Assert.Throws<ArgumentException>(() => e.GetComponent<SoftBody>()!.friction = -1f);
        }
    }
}
