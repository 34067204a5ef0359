using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    public class SoftSceneTests
    {
        static string Jelly(string extra = "") => @"{
  ""format"": ""fulcrum-scene/1"",
  ""bodies"": [
    { ""name"": ""ground"", ""type"": ""static"", ""shape"": { ""type"": ""box"", ""halfExtents"": [10, 0.5, 10] }, ""position"": [0, -0.5, 0] },
    { ""name"": ""hook"", ""type"": ""static"", ""shape"": { ""type"": ""sphere"", ""radius"": 0.1 }, ""position"": [0, 5, 0] }
  ],
  ""softBodies"": [
    { ""name"": ""jelly"",
      ""mesh"": { ""type"": ""box"", ""size"": [1, 1, 1], ""cells"": [2, 2, 2] },
      ""material"": { ""model"": ""stable-neo-hookean"", ""youngsModulus"": 1e5, ""poissonRatio"": 0.45, ""density"": 1000 },
      ""position"": [0, 2, 0],
      ""probes"": [[0, 0.5, 0]]EXTRA }
  ]
}".Replace("EXTRA", extra);

        [Test]
        public void Scene_soft_bodies_are_created_with_their_material_position_and_probes()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(Jelly()));
            SoftBodyHandle[] made = SceneSoftBodyBuilder.Build(scene);
            Assert.That(made, Has.Length.EqualTo(1));
            SoftBody body = scene.World.GetSoftBody(made[0]);
            Assert.That(body.Name, Is.EqualTo("jelly"));
            Assert.That(body.TotalMass, Is.EqualTo(1000f).Within(1e-2f));
            Assert.That(body.ComputeStats().Centroid.Y, Is.EqualTo(2f).Within(1e-5f));
            Assert.That(Vector3.Distance(body.GetProbe(0), new Vector3(0, 2.5f, 0)), Is.LessThan(1e-5f));
        }

        [Test]
        public void A_pin_box_in_the_scene_holds_the_jelly_up()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(Jelly(", \"pinned\": [{ \"min\": [-1, 0.4, -1], \"max\": [1, 1, 1] }]")));
            SoftBodyHandle[] made = SceneSoftBodyBuilder.Build(scene);
            for (int n = 0; n < 60; n++) scene.World.Step(1f / 60f);
            // The top face is fixed; the body hangs from it instead of falling to the ground.
            Assert.That(scene.World.GetSoftBody(made[0]).GetProbe(0).Y, Is.EqualTo(2.5f).Within(1e-4f));
            Assert.That(scene.World.GetSoftBody(made[0]).ComputeStats().Centroid.Y, Is.GreaterThan(1.8f));
        }

        [Test]
        public void A_pin_box_that_selects_no_vertex_names_the_soft_body_and_creates_nothing()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(Jelly(", \"pinned\": [{ \"min\": [3, 3, 3], \"max\": [4, 4, 4] }]")));
            var e = Assert.Throws<SceneException>(() => SceneSoftBodyBuilder.Build(scene))!;
            Assert.That(e.Message, Does.StartWith("$.softBodies[0]"));
            Assert.That(scene.World.SoftBodyCount(), Is.EqualTo(0));
        }
    }
}
