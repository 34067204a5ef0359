using System;
using System.Numerics;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    public class SceneBuilderTests
    {
        [Test]
        public void The_design_example_builds_every_body_and_keeps_joints_and_soft_bodies_as_data()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(SceneSamples.DesignExample));
            World world = scene.World;
            Assert.That(world.BodyCount, Is.EqualTo(22));
            Assert.That(scene.BodyHandles.Count, Is.EqualTo(22));
            Assert.That(scene.BodyName(2), Is.EqualTo("tower/0"));
            Assert.That(world.GetBody(scene.GetBody("ground")).Type, Is.EqualTo(BodyType.Static));
            Assert.That(world.GetBody(scene.GetBody("ball")).Mass, Is.EqualTo(700f * 4f / 3f * MathF.PI * 0.125f).Within(1e-3f), "from the wood density");
            Assert.That(world.GetBody(scene.GetBody("tower/19")).Mass, Is.EqualTo(1000f), "1 m^3 at the default density");
            Assert.That(world.GetBody(scene.GetBody("tower/19")).Position, Is.EqualTo(new Vector3(0, 19.5f, 0)));
            Assert.That(world.Settings.Solver, Is.EqualTo(SolverType.Tgs));
            Assert.That(scene.Timestep, Is.EqualTo(0.0166667f));
            Assert.That(scene.Joints.Count, Is.EqualTo(1));
            Assert.That(scene.JointHandles, Has.Count.EqualTo(1));
            Assert.That(world.IsValid(scene.JointHandles[0]), Is.True);
            Assert.That(scene.SoftBodies.Count, Is.EqualTo(1));
            Assert.Throws<System.Collections.Generic.KeyNotFoundException>(() => scene.GetBody("nobody"));
        }

        [Test]
        public void Settings_come_from_the_scene_and_the_rest_from_the_given_settings()
        {
            SceneDocument doc = SceneFile.Parse(SceneSamples.OneBall());
            doc.Gravity = new Vector3(0, -3.7f, 0);
            doc.Solver.Type = SolverType.Pgs;
            doc.Solver.Iterations = 9;
            WorldSettings baseSettings = WorldSettings.Default;
            baseSettings.Threads = 3;
            World world = SceneBuilder.Build(doc, baseSettings).World;
            Assert.That(world.Gravity, Is.EqualTo(new Vector3(0, -3.7f, 0)));
            Assert.That(world.Settings.Solver, Is.EqualTo(SolverType.Pgs));
            Assert.That(world.Settings.Iterations, Is.EqualTo(9));
            Assert.That(world.Settings.Threads, Is.EqualTo(3));
        }

        [Test]
        public void A_material_density_gives_the_mass_and_its_friction_reaches_the_shape()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(SceneSamples.OneBall(", \"material\": \"wood\"")));
            BodyHandle ball = scene.GetBody("ball");
            Assert.That(scene.World.GetBody(ball).Mass, Is.EqualTo(700f * 4f / 3f * MathF.PI * 0.125f).Within(1e-3f));
            Span<ShapeHandle> shapes = stackalloc ShapeHandle[1];
            scene.World.GetShapes(ball, shapes);
            Assert.That(scene.World.Shapes.Friction[shapes[0].Index], Is.EqualTo(0.5f));
        }

        [Test]
        public void A_compound_puts_each_child_on_the_body_at_its_pose()
        {
            string shape = "{ \"type\": \"compound\", \"children\": [ { \"shape\": { \"type\": \"sphere\", \"radius\": 0.5 }, \"position\": [-1, 0, 0] }, { \"shape\": { \"type\": \"box\", \"halfExtents\": [0.5, 0.5, 0.5] }, \"position\": [1, 0, 0] } ] }";
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(SceneSamples.OneBall(shape: shape)));
            BodyHandle body = scene.GetBody("ball");
            Span<ShapeHandle> shapes = stackalloc ShapeHandle[4];
            Assert.That(scene.World.GetShapes(body, shapes), Is.EqualTo(2));
            float sphere = 1000f * 4f / 3f * MathF.PI * 0.125f, box = 1000f;
            Assert.That(scene.World.GetBody(body).Mass, Is.EqualTo(sphere + box).Within(1e-2f));
            Assert.That(scene.World.GetBody(body).LocalCenterOfMass.X, Is.EqualTo((box - sphere) / (box + sphere)).Within(1e-5f));
        }

        [Test]
        public void A_convex_shape_builds_a_hull_with_its_polyhedral_mass()
        {
            // The unit corner tetrahedron: volume 1/6, centroid (1/4, 1/4, 1/4).
            string shape = "{ \"type\": \"convex\", \"points\": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]] }";
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(SceneSamples.OneBall(shape: shape)));
            BodyHandle body = scene.GetBody("ball");
            Assert.That(scene.World.GetBody(body).Mass, Is.EqualTo(1000f / 6f).Within(1e-2f));
            Assert.That(scene.World.GetBody(body).LocalCenterOfMass.X, Is.EqualTo(0.25f).Within(1e-5f));
        }

        [Test]
        public void A_flat_convex_shape_is_refused_at_its_path()
        {
            string shape = "{ \"type\": \"compound\", \"children\": [ { \"shape\": { \"type\": \"sphere\", \"radius\": 0.5 } }, { \"shape\": { \"type\": \"convex\", \"points\": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]] } } ] }";
            SceneDocument doc = SceneFile.Parse(SceneSamples.OneBall(shape: shape));
            var e = Assert.Throws<SceneException>(() => SceneBuilder.Build(doc))!;
            Assert.That(e.Message, Does.StartWith("$.bodies[0].shape.children[1].shape: "));
        }

        [Test]
        public void An_invalid_document_is_refused_before_a_world_exists()
        {
            var doc = new SceneDocument();
            doc.Bodies.Add(new SceneBody { Name = "b", Shape = new SceneSphere { Radius = -1 } });
            var e = Assert.Throws<SceneException>(() => SceneBuilder.Build(doc))!;
            Assert.That(e.Message, Is.EqualTo("$.bodies[0].shape.radius: must be > 0, got -1"));
        }

        [Test]
        public void Generated_dominoes_start_with_their_tip_velocity()
        {
            var doc = new SceneDocument();
            doc.Generators.Add(new SceneDominoes { Count = 2, TipSpeed = 3 });
            SceneInstance scene = SceneBuilder.Build(doc);
            BodyRef first = scene.World.GetBody(scene.GetBody("dominoes/0"));
            Assert.That(first.AngularVelocity, Is.EqualTo(new Vector3(0, 0, -3)));
            Assert.That(first.LinearVelocity.X, Is.EqualTo(1.5f).Within(1e-6f), "w h/2 at the centre, h = 1");
        }
    }
}
