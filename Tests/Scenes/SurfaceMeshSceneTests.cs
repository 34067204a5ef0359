using System;
using System.IO;
using System.Linq;
using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    /// <summary>The <c>surface</c> soft mesh kind: a closed OBJ surface tetrahedralised at load.</summary>
    public class SurfaceMeshSceneTests
    {
        static string Scene(string mesh) => $@"{{
  ""format"": ""fulcrum-scene/1"",
  ""softBodies"": [
    {{ ""name"": ""s"", ""mesh"": {mesh},
      ""material"": {{ ""youngsModulus"": 1e5, ""poissonRatio"": 0.3, ""density"": 500 }}, ""position"": [0, 1, 0] }}
  ]
}}";

        static string ScenesDir() => PackageRoot.ScenesDirectory;

        [Test]
        public void Surface_mesh_reads_with_default_resolution_and_saves_back()
        {
            SceneDocument doc = SceneFile.Parse(Scene("{ \"type\": \"surface\", \"file\": \"meshes/blob.obj\" }"));
            var surface = (SceneSoftSurface)doc.SoftBodies[0].Mesh!;
            Assert.That((surface.File, surface.Resolution, surface.IsShell), Is.EqualTo(("meshes/blob.obj", 8, false)));
            Assert.That(SceneFile.Save(doc), Does.Contain("\"type\": \"surface\"").And.Contain("\"resolution\": 8"));
        }

        [TestCase("{ \"type\": \"surface\", \"file\": \"b.obj\", \"resolution\": 1 }", "$.softBodies[0].mesh.resolution: must be in [2, 64], got 1")]
        [TestCase("{ \"type\": \"surface\", \"file\": \"b.obj\", \"resolution\": 65 }", "$.softBodies[0].mesh.resolution: must be in [2, 64], got 65")]
        public void Bad_resolution_is_reported_at_its_path(string mesh, string error)
        {
            var errors = SceneFile.Check(Scene(mesh), out _).Select(e => $"{e.Path}: {e.Message}").ToList();
            Assert.That(errors, Has.Member(error));
        }

        [Test]
        public void Blob_sample_builds_a_volume_mesh_that_falls_and_rests_on_the_ground()
        {
            string dir = ScenesDir();
            SceneInstance scene = SceneBuilder.Build(SceneFile.Load(Path.Combine(dir, "blob-drop.json")));
            SoftBody blob = scene.World.GetSoftBody(SceneSoftBodyBuilder.Build(scene, directory: dir)[0]);
            Assert.That(blob.Mesh.TetrahedronCount, Is.GreaterThan(100));
            for (int n = 0; n < 120; n++) scene.World.Step(scene.Timestep);
            float lowest = float.MaxValue;
            foreach (Vector3 p in blob.Positions)
            {
                Assert.That(float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z), Is.True);
                lowest = MathF.Min(lowest, p.Y);
            }
            // Fallen from 0.6 m onto the ground top at y = 0: resting on it, not through it.
            Assert.That(lowest, Is.EqualTo(0f).Within(0.03f));
        }
    }
}
