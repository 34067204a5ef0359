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
    
        [Test]
        public void Solver_settings_set_before_or_after_the_mesh_reach_the_soft_body()
        {
            var scene = new PhysicsScene(WorldSettings.Default, 1f / 60f);
            Entity e = scene.CreateEntity("Block", new Vector3(0, 2, 0));
            var soft = e.AddComponent<SoftBody>();
            soft.solver = SoftSolver.Newton;
            soft.iterations = 3;
            soft.mesh = SoftMesh.Box(new Vector3(0.4f), 2, 2, 2);
            Assert.That(soft.body!.Solver, Is.EqualTo(SoftSolver.Newton));
            Assert.That(soft.body.Iterations, Is.EqualTo(3));
            soft.substeps = 7;
            soft.dampingTime = 0.02f;
            soft.solver = SoftSolver.Xpbd;
            Assert.That(soft.body.Substeps, Is.EqualTo(7));
            Assert.That(soft.body.DampingTime, Is.EqualTo(0.02f));
            Assert.That(soft.body.Solver, Is.EqualTo(SoftSolver.Xpbd));
            Assert.Throws<ArgumentException>(() => soft.substeps = -1);
            Assert.Throws<ArgumentException>(() => soft.iterations = 0);
            Assert.Throws<ArgumentException>(() => soft.dampingTime = float.NaN);
            for (int k = 0; k < 30; k++) scene.Tick(1f / 60f);
            Assert.That(soft.body.ComputeStats().Centroid.Y, Is.LessThan(2f), "it steps with the new settings");
        }
    }
}
