using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    /// <summary>The soft mesh kinds of the scene format: reading, errors at their paths, and building.</summary>
    public class SoftMeshSceneTests
    {
        static string Scene(string mesh, string extra = "") => $@"{{
  ""format"": ""fulcrum-scene/1"",
  ""softBodies"": [
    {{ ""name"": ""s"", ""mesh"": {mesh},
      ""material"": {{ ""youngsModulus"": 1e5, ""poissonRatio"": 0.3, ""density"": 500 }}, ""position"": [1, 2, 3]{extra} }}
  ]
}}";

        static List<string> Errors(string text) => SceneFile.Check(text, out _).Select(e => $"{e.Path}: {e.Message}").ToList();

        static SoftBody Built(string text, string? directory = null)
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(text));
            return scene.World.GetSoftBody(SceneSoftBodyBuilder.Build(scene, directory: directory)[0]);
        }

        [Test]
        public void Every_soft_mesh_kind_of_the_everything_sample_is_read_with_its_fields()
        {
            SceneDocument doc = SceneFile.Parse(SceneSamples.Everything);
            var sphere = (SceneSoftSphere)doc.SoftBodies[1].Mesh!;
            Assert.That((sphere.Radius, sphere.Cells), Is.EqualTo((0.3f, 5)));
            var capsule = (SceneSoftCapsule)doc.SoftBodies[2].Mesh!;
            Assert.That((capsule.Radius, capsule.HalfHeight, capsule.Cells), Is.EqualTo((0.2f, 0.35f, 4)));
            var beam = (SceneSoftBeam)doc.SoftBodies[3].Mesh!;
            Assert.That((beam.Length, beam.Thickness, beam.Cells), Is.EqualTo((1.7f, 0.1f, 17)));
            var cloth = (SceneSoftCloth)doc.SoftBodies[4].Mesh!;
            Assert.That(cloth.Size, Is.EqualTo(new Vector2(1.5f, 0.75f)));
            Assert.That(cloth.Cells, Is.EqualTo(new[] { 6, 3 }));
            Assert.That((cloth.Thickness, cloth.BendingScale), Is.EqualTo((0.001f, 0.25f)));
            var tetgen = (SceneSoftTetGen)doc.SoftBodies[5].Mesh!;
            Assert.That((tetgen.Node, tetgen.Ele), Is.EqualTo(("meshes/ball.node", "meshes/ball.ele")));
            var obj = (SceneSoftObj)doc.SoftBodies[6].Mesh!;
            Assert.That((obj.File, obj.Thickness, obj.BendingScale), Is.EqualTo((@"C:\sails\jib.obj", 0.002f, 0f)));
            Assert.That(doc.SoftBodies.Select(s => s.Mesh!.IsShell), Is.EqualTo(new[] { false, false, false, false, true, false, true }));
        }

        [Test]
        public void Omitted_mesh_fields_take_their_documented_defaults_and_save_back_explicitly()
        {
            SceneDocument doc = SceneFile.Parse(Scene("{ \"type\": \"cloth\", \"size\": [2, 1] }"));
            var cloth = (SceneSoftCloth)doc.SoftBodies[0].Mesh!;
            Assert.That(cloth.Cells, Is.EqualTo(new[] { 1, 1 }));
            Assert.That((cloth.Thickness, cloth.BendingScale), Is.EqualTo((0.0005f, 1f)));
            Assert.That(((SceneSoftSphere)SceneFile.Parse(Scene("{ \"type\": \"sphere\", \"radius\": 1 }")).SoftBodies[0].Mesh!).Cells, Is.EqualTo(6));
            Assert.That(SceneFile.Save(doc), Does.Contain("\"thickness\": 0.0005").And.Contain("\"cells\": [1, 1]"));
        }

        [TestCase("{ \"type\": \"sphere\", \"radius\": 0.5, \"cells\": 1 }", "$.softBodies[0].mesh.cells: must be in [4, 1024], got 1")]
        [TestCase("{ \"type\": \"capsule\", \"radius\": 0.5, \"halfHeight\": 0.2, \"cells\": 3 }", "$.softBodies[0].mesh.cells: must be in [4, 1024], got 3")]
        [TestCase("{ \"type\": \"sphere\", \"radius\": -0.5 }", "$.softBodies[0].mesh.radius: must be > 0, got -0.5")]
        [TestCase("{ \"type\": \"sphere\", \"radius\": 1, \"cells\": 200 }", "$.softBodies[0].mesh.cells: more than 1000000 cells (200^3)")]
        [TestCase("{ \"type\": \"capsule\", \"radius\": 0.5, \"halfHeight\": -1 }", "$.softBodies[0].mesh.halfHeight: must be >= 0, got -1")]
        [TestCase("{ \"type\": \"capsule\", \"radius\": 0.5 }", "$.softBodies[0].mesh.halfHeight: missing required field")]
        [TestCase("{ \"type\": \"beam\", \"length\": 2, \"thickness\": 0, \"cells\": 4 }", "$.softBodies[0].mesh.thickness: must be > 0, got 0")]
        [TestCase("{ \"type\": \"cloth\", \"size\": [1, 0], \"cells\": [4, 4] }", "$.softBodies[0].mesh.size[1]: must be > 0, got 0")]
        [TestCase("{ \"type\": \"cloth\", \"size\": [1, 1, 1] }", "$.softBodies[0].mesh.size: expected a size [x, z], got an array of 3")]
        [TestCase("{ \"type\": \"cloth\", \"size\": [1, 1], \"cells\": [4, 0] }", "$.softBodies[0].mesh.cells[1]: must be in [1, 1024], got 0")]
        [TestCase("{ \"type\": \"cloth\", \"size\": [1, 1], \"thickness\": 0 }", "$.softBodies[0].mesh.thickness: must be > 0, got 0")]
        [TestCase("{ \"type\": \"cloth\", \"size\": [1, 1], \"bendingScale\": -1 }", "$.softBodies[0].mesh.bendingScale: must be >= 0, got -1")]
        [TestCase("{ \"type\": \"tetgen\", \"node\": \"a.node\" }", "$.softBodies[0].mesh.ele: missing required field")]
        [TestCase("{ \"type\": \"tetgen\", \"node\": \" \", \"ele\": \"a.ele\" }", "$.softBodies[0].mesh.node: must be a non-empty file path")]
        [TestCase("{ \"type\": \"obj\" }", "$.softBodies[0].mesh.file: missing required field")]
        [TestCase("{ \"type\": \"box\", \"size\": [1, 1, 1], \"split\": \"seven\" }", "$.softBodies[0].mesh.split: unknown split 'seven' (expected six, six-mirrored or five)")]
        [TestCase("{ \"type\": \"torus\", \"radius\": 1 }", "$.softBodies[0].mesh.type: unknown soft mesh type 'torus' (expected box, sphere, capsule, beam, cloth, tetgen, surface or obj)")]
        public void A_bad_mesh_field_is_one_error_at_its_path(string mesh, string expected)
        {
            Assert.That(Errors(Scene(mesh)), Is.EqualTo(new[] { expected }));
        }

        [TestCase(null, "six")]
        [TestCase("six-mirrored", "six-mirrored")]
        [TestCase("five", "five")]
        public void A_box_split_is_read_and_saved_back(string? split, string expected)
        {
            string field = split == null ? "" : $", \"split\": \"{split}\"";
            SceneDocument doc = SceneFile.Parse(Scene("{ \"type\": \"box\", \"size\": [1, 1, 1], \"cells\": [2, 2, 2]" + field + " }"));
            Assert.That(((SceneSoftBox)doc.SoftBodies[0].Mesh!).Split, Is.EqualTo(expected));
            string saved = SceneFile.Save(doc);
            Assert.That(((SceneSoftBox)SceneFile.Parse(saved).SoftBodies[0].Mesh!).Split, Is.EqualTo(expected));
            if (split == null) Assert.That(saved, Does.Not.Contain("split"), "the default is left out");
        }

        [Test]
        public void A_field_of_another_mesh_kind_is_an_unknown_field()
        {
            List<string> errors = Errors(Scene("{ \"type\": \"sphere\", \"radius\": 1, \"size\": [1, 1, 1] }"));
            Assert.That(errors, Has.Count.EqualTo(1));
            Assert.That(errors[0], Does.StartWith("$.softBodies[0].mesh.size: unknown field (expected one of: type, radius, cells"));
        }

        [Test]
        public void Plasticity_on_a_cloth_shell_is_an_error()
        {
            Assert.That(Errors(Scene("{ \"type\": \"cloth\", \"size\": [1, 1] }", ", \"plasticity\": { \"flowRate\": 1 }")),
                Is.EqualTo(new[] { "$.softBodies[0].plasticity: needs a volume mesh; a cloth mesh is a triangle shell" }));
        }

        [Test]
        public void A_sphere_mesh_builds_a_ball_of_the_radius_about_the_position()
        {
            SoftBody ball = Built(Scene("{ \"type\": \"sphere\", \"radius\": 0.4, \"cells\": 8 }"));
            SoftBodyStats s = ball.ComputeStats();
            float volume = 4f / 3f * MathF.PI * 0.4f * 0.4f * 0.4f;
            Assert.That(ball.IsShell, Is.False);
            // A carved grid of 8 cells across, scaled to the ball's volume.
            Assert.That(s.RestVolume, Is.EqualTo(volume).Within(0.03f * volume));
            Assert.That(ball.TotalMass, Is.EqualTo(500f * s.RestVolume).Within(1e-3f * ball.TotalMass));
            Vector3 lo = new Vector3(float.MaxValue), hi = new Vector3(float.MinValue);
            foreach (Vector3 x in ball.Positions) { lo = Vector3.Min(lo, x); hi = Vector3.Max(hi, x); }
            TestContext.Out.WriteLine($"sphere r 0.4, 8 cells: rest volume {s.RestVolume / volume:F4} of the ball's, bounds {lo} .. {hi}");
            // Within 1 mm: the mesh smoothing visits vertices in order, so the ball is not exactly symmetric.
            Assert.That(((lo + hi) / 2 - new Vector3(1, 2, 3)).Length(), Is.LessThan(1e-3f), "centred on the position");
            Assert.That(hi.X - lo.X, Is.EqualTo(0.8f).Within(0.05f * 0.8f), "a diameter across");
        }

        [Test]
        public void A_capsule_and_a_beam_build_with_their_dimensions()
        {
            SoftBody capsule = Built(Scene("{ \"type\": \"capsule\", \"radius\": 0.2, \"halfHeight\": 0.3, \"cells\": 6 }"));
            float top = float.MinValue, bottom = float.MaxValue;
            foreach (Vector3 x in capsule.Positions) { top = MathF.Max(top, x.Y); bottom = MathF.Min(bottom, x.Y); }
            // The mesh smoothing slides surface vertices along the surface, the poles included.
            Assert.That(top - bottom, Is.EqualTo(2 * 0.3f + 2 * 0.2f).Within(0.005f));

            SoftBody beam = Built(Scene("{ \"type\": \"beam\", \"length\": 2, \"thickness\": 0.2, \"cells\": 10 }"));
            Assert.That(beam.ComputeStats().RestVolume, Is.EqualTo(2f * 0.2f * 0.2f).Within(1e-5f));
            Assert.That(beam.VertexCount, Is.EqualTo(11 * 2 * 2), "10 cells along, one across");
        }

        [Test]
        public void A_cloth_mesh_builds_a_shell_with_its_grid_thickness_and_mass()
        {
            SoftBody cloth = Built(Scene("{ \"type\": \"cloth\", \"size\": [1.5, 1], \"cells\": [6, 4], \"thickness\": 0.002, \"bendingScale\": 0.5 }"));
            Assert.That(cloth.IsShell, Is.True);
            Assert.That(cloth.VertexCount, Is.EqualTo(7 * 5));
            Assert.That(cloth.ElementCount, Is.EqualTo(6 * 4 * 2), "two triangles a cell");
            Assert.That(cloth.Thickness, Is.EqualTo(0.002f));
            Assert.That(cloth.TotalMass, Is.EqualTo(500f * 1.5f * 1f * 0.002f).Within(1e-5f), "density x area x thickness");
            foreach (Vector3 x in cloth.Positions) Assert.That(x.Y, Is.EqualTo(2f));
        }

        [Test]
        public void Tetgen_and_obj_files_are_read_relative_to_the_scene_folder_and_centred_on_the_position()
        {
            string dir = Path.Combine(Path.GetTempPath(), "fulcrum-softmesh-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Path.Combine(dir, "meshes"));
            try
            {
                // One tetrahedron whose bounds' centre is (10.5, 0.5, 0.5), far from the file origin.
                File.WriteAllText(Path.Combine(dir, "meshes", "tet.node"), "4 3 0 0\n0 10 0 0\n1 11 0 0\n2 10 1 0\n3 10 0 1\n");
                File.WriteAllText(Path.Combine(dir, "meshes", "tet.ele"), "1 4 0\n0 0 1 2 3\n");
                File.WriteAllText(Path.Combine(dir, "meshes", "quad.obj"), "v 0 0 0\nv 2 0 0\nv 2 0 2\nv 0 0 2\nf 1 3 2\nf 1 4 3\n");

                SoftBody tet = Built(Scene("{ \"type\": \"tetgen\", \"node\": \"meshes/tet.node\", \"ele\": \"meshes/tet.ele\" }",
                    ", \"probes\": [[-0.5, -0.5, -0.5]]"), dir);
                Assert.That(tet.Mesh.TetrahedronCount, Is.EqualTo(1));
                Assert.That(tet.Positions[0], Is.EqualTo(new Vector3(0.5f, 1.5f, 2.5f)), "bounds centre at the position");
                Assert.That(tet.GetProbe(0), Is.EqualTo(new Vector3(0.5f, 1.5f, 2.5f)), "probes are about the centre too");

                SoftBody quad = Built(Scene("{ \"type\": \"obj\", \"file\": \"meshes/quad.obj\", \"thickness\": 0.01 }",
                    ", \"pinned\": [{ \"min\": [-1, 0, -1], \"max\": [-1, 0, 1] }]"), dir);
                Assert.That(quad.IsShell, Is.True);
                Assert.That(quad.Positions[0], Is.EqualTo(new Vector3(0f, 2f, 2f)));
                Assert.That(quad.InverseMasses[0], Is.EqualTo(0f), "the pin box about the centre holds the x = 0 edge");
                Assert.That(quad.InverseMasses[1], Is.GreaterThan(0f));
                Assert.That(quad.TotalMass, Is.EqualTo(500f * 4f * 0.01f).Within(1e-4f));
            }
            finally
            {
                Directory.Delete(dir, true);
            }
        }

        [Test]
        public void A_missing_mesh_file_is_a_scene_error_at_the_field_and_creates_nothing()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(Scene("{ \"type\": \"tetgen\", \"node\": \"no-such.node\", \"ele\": \"no-such.ele\" }")));
            var e = Assert.Throws<SceneException>(() => SceneSoftBodyBuilder.Build(scene, directory: Path.GetTempPath()))!;
            Assert.That(e.Errors[0].Path, Is.EqualTo("$.softBodies[0].mesh.node"));
            Assert.That(e.Errors[0].Message, Does.Contain("no-such.node"));
            Assert.That(scene.World.SoftBodyCount(), Is.EqualTo(0));
        }
    }
}
