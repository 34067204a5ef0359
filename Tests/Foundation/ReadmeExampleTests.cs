using System.IO;
using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Foundation
{
    /// <summary>The README's code, kept compiling and behaving as the README says.</summary>
    public class ReadmeExampleTests
    {
        [Test]
        public void Quick_start_box_lands_on_the_ground_and_reports_contacts()
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(20, 0.5f, 20))));
            BodyHandle box = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 3, 0)));
            world.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            world.AddForce(box, new Vector3(0, 0, 200), ForceMode.Impulse);
            int begins = 0;
            for (int i = 0; i < 120; i++)
            {
                world.Step(1f / 60f);
                foreach (var e in world.ContactEvents)
                    if (e.Kind == Fulcrum.Collision.ContactEventKind.Begin) begins++;
            }
            Assert.That(world.GetBody(box).Position.Y, Is.EqualTo(0.5f).Within(0.01f), "resting on the ground");
            Assert.That(world.GetBody(box).Position.Z, Is.GreaterThan(0.1f), "the impulse pushed it along z");
            Assert.That(begins, Is.EqualTo(1), "one landing, one Begin");
        }

        [Test]
        public void Scene_with_soft_bodies_runs_as_in_the_readme()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Load(Path.Combine(PackageRoot.ScenesDirectory, "jelly.json")));
            SceneSoftBodyBuilder.Build(scene);
            for (int i = 0; i < 180; i++) scene.World.Step(scene.Timestep);
            Assert.That(scene.World.SoftBodyCount(), Is.EqualTo(1));
        }

        [Test]
        public void Soft_body_quick_start_keeps_its_volume()
        {
            var world = new World();
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(1, 1, 1), 4, 4, 4), MaterialPresets.Jelly, new Vector3(0, 2, 0));
            SoftBodyHandle jelly = world.CreateSoftBody(def);
            world.Step(1f / 60f);
            SoftBodyStats s = world.GetSoftBody(jelly).ComputeStats();
            Assert.That(s.VolumeRatio, Is.EqualTo(1f).Within(0.01f));
        }
    }
}
