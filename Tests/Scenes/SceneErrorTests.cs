using System.Collections.Generic;
using System.Linq;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    public class SceneErrorTests
    {
        static IReadOnlyList<SceneError> Errors(string text) => SceneFile.Check(text, out _);

        static SceneError OnlyError(string text)
        {
            IReadOnlyList<SceneError> errors = Errors(text);
            Assert.That(errors.Select(e => e.ToString()).ToList(), Has.Count.EqualTo(1));
            return errors[0];
        }

        [Test]
        public void A_valid_scene_has_no_errors()
        {
            Assert.That(Errors(SceneSamples.OneBall()), Is.Empty);
            Assert.That(Errors(SceneSamples.Everything), Is.Empty);
        }

        [Test]
        public void An_unknown_field_is_an_error_at_its_path_listing_the_known_ones()
        {
            SceneError e = OnlyError(SceneSamples.OneBall(", \"colour\": \"red\""));
            Assert.That(e.Path, Is.EqualTo("$.bodies[0].colour"));
            Assert.That(e.Message, Does.StartWith("unknown field (expected one of: name, type, shape, mass, density, material,"));
            Assert.That(e.Line, Is.EqualTo(5));
        }

        [Test]
        public void A_wrong_type_names_the_path_and_what_was_found()
        {
            SceneError e = OnlyError(SceneSamples.OneBall(", \"mass\": \"heavy\""));
            Assert.That(e.ToString(), Does.StartWith("$.bodies[0].mass: expected a number, got \"heavy\" (line 5, column"));
        }

        [Test]
        public void A_fraction_where_an_integer_belongs_is_an_error()
        {
            string text = SceneSamples.OneBall().Replace("\"materials\"", "\"solver\": { \"iterations\": 4.5 }, \"materials\"");
            Assert.That(OnlyError(text).ToString(), Does.StartWith("$.solver.iterations: expected an integer, got 4.5"));
        }

        [Test]
        public void An_unknown_shape_type_is_one_error_at_the_type()
        {
            SceneError e = OnlyError(SceneSamples.OneBall(shape: "{ \"type\": \"cylinder\", \"radius\": 1 }"));
            Assert.That(e.Path, Is.EqualTo("$.bodies[0].shape.type"));
            Assert.That(e.Message, Does.StartWith("unknown shape type 'cylinder'"));
        }

        [Test]
        public void A_negative_radius_names_the_radius_and_its_line()
        {
            SceneError e = OnlyError(SceneSamples.OneBall(shape: "{ \"type\": \"sphere\", \"radius\": -1 }"));
            Assert.That(e.Path, Is.EqualTo("$.bodies[0].shape.radius"));
            Assert.That(e.Message, Is.EqualTo("must be > 0, got -1"));
            Assert.That((e.Line, e.Column), Is.EqualTo((5, 62)));
        }

        [Test]
        public void Mass_and_density_on_one_body_is_an_error()
        {
            SceneError e = OnlyError(SceneSamples.OneBall(", \"mass\": 2, \"density\": 300"));
            Assert.That(e.ToString(), Does.StartWith("$.bodies[0].density: mass and density are both given: give one"));
        }

        [Test]
        public void Mass_overrides_the_density_of_the_material()
        {
            SceneDocument doc = SceneFile.Parse(SceneSamples.OneBall(", \"mass\": 2, \"material\": \"wood\""));
            var instance = SceneBuilder.Build(doc);
            Assert.That(instance.World.GetBody(instance.GetBody("ball")).Mass, Is.EqualTo(2f).Within(1e-5f));
        }

        [Test]
        public void A_body_density_overrides_the_material_density()
        {
            SceneDocument doc = SceneFile.Parse(SceneSamples.OneBall(", \"density\": 300, \"material\": \"wood\""));
            var instance = SceneBuilder.Build(doc);
            float expected = MassProperties.Sphere(0.5f, 300f).Mass;
            Assert.That(instance.World.GetBody(instance.GetBody("ball")).Mass, Is.EqualTo(expected).Within(1e-3f));
        }

        [Test]
        public void A_missing_material_is_an_error_at_the_reference()
        {
            SceneError e = OnlyError(SceneSamples.OneBall(", \"material\": \"steel\""));
            Assert.That(e.Path, Is.EqualTo("$.bodies[0].material"));
            Assert.That(e.Message, Is.EqualTo("no material named 'steel' in $.materials"));
        }

        [Test]
        public void A_bad_format_string_is_an_error()
        {
            SceneError e = OnlyError(SceneSamples.OneBall().Replace("fulcrum-scene/1", "fulcrum-scene/2"));
            Assert.That(e.ToString(), Is.EqualTo("$.format: must be \"fulcrum-scene/1\", got \"fulcrum-scene/2\" (line 2, column 13)"));
        }

        [Test]
        public void A_missing_required_field_is_an_error_at_its_path()
        {
            SceneError e = OnlyError(SceneSamples.OneBall().Replace("\"name\": \"ball\", ", ""));
            Assert.That(e.Path, Is.EqualTo("$.bodies[0].name"));
            Assert.That(e.Message, Is.EqualTo("missing required field"));
            Assert.That(OnlyError("{}").Path, Is.EqualTo("$.format"));
        }

        [Test]
        public void A_plane_on_a_dynamic_body_is_an_error()
        {
            SceneError e = OnlyError(SceneSamples.OneBall(shape: "{ \"type\": \"plane\" }"));
            Assert.That(e.ToString(), Does.StartWith("$.bodies[0].shape.type: a plane can only be the shape of a static body"));
        }

        [Test]
        public void Joints_must_name_existing_bodies()
        {
            string text = SceneSamples.OneBall().Replace("\"bodies\"",
                "\"joints\": [{ \"type\": \"ball\", \"bodyA\": \"ball\", \"bodyB\": \"nobody\" }], \"bodies\"");
            SceneError e = OnlyError(text);
            Assert.That(e.Path, Is.EqualTo("$.joints[0].bodyB"));
            Assert.That(e.Message, Is.EqualTo("no body named 'nobody'"));
        }

        [Test]
        public void A_generated_name_that_clashes_with_a_body_is_an_error_at_the_generator()
        {
            string text = SceneSamples.OneBall().Replace("\"name\": \"ball\"", "\"name\": \"tower/1\"")
                .Replace("\"bodies\"", "\"generators\": [{ \"type\": \"tower\", \"count\": 3 }], \"bodies\"");
            SceneError e = OnlyError(text);
            Assert.That(e.Path, Is.EqualTo("$.generators[0]"));
            Assert.That(e.Message, Does.StartWith("generated body name 'tower/1' is already used at $.bodies[0]"));
        }

        [Test]
        public void A_rejected_generator_does_not_also_orphan_the_joints_naming_its_bodies()
        {
            string text = SceneSamples.OneBall().Replace("\"bodies\"",
                "\"generators\": [{ \"type\": \"chain\", \"count\": 4, \"spacing\": -1 }], \"joints\": [{ \"type\": \"ball\", \"bodyA\": \"ball\", \"bodyB\": \"chain/3\" }], \"bodies\"");
            Assert.That(OnlyError(text).ToString(), Does.StartWith("$.generators[0].spacing: must be >= 0, got -1"));
        }

        [Test]
        public void Every_error_is_reported_at_once_structural_ones_first()
        {
            string text = @"{
  ""format"": ""fulcrum-scene/1"",
  ""timestep"": 0,
  ""bodies"": [
    { ""name"": ""a"", ""shape"": { ""type"": ""box"", ""halfExtents"": [1, 0, 1] }, ""spin"": 3 },
    { ""name"": ""a"", ""shape"": { ""type"": ""capsule"", ""radius"": 1 } }
  ],
  ""softBodies"": [ { ""name"": ""s"", ""mesh"": { ""type"": ""box"", ""size"": [1, 1, 1] },
                    ""material"": { ""youngsModulus"": 1000, ""poissonRatio"": 0.5 } } ]
}";
            Assert.That(Errors(text).Select(e => e.Path + ": " + e.Message).ToList(), Is.EqualTo(new[]
            {
                "$.bodies[0].spin: unknown field (expected one of: name, type, shape, mass, density, material, position, rotation, velocity, angularVelocity, ccd, lockAxes)",
                "$.bodies[1].shape.halfHeight: missing required field",
                "$.timestep: must be > 0, got 0",
                "$.bodies[0].shape.halfExtents: must be > 0 on every axis, got [1, 0, 1]",
                "$.bodies[1].name: duplicate body name 'a' (first used at $.bodies[0])",
                "$.softBodies[0].material.poissonRatio: must be in (-1, 0.5), got 0.5",
            }));
        }

        [Test]
        public void Parse_throws_a_scene_exception_carrying_every_error()
        {
            var ex = Assert.Throws<SceneException>(() => SceneFile.Parse(SceneSamples.OneBall(", \"mass\": -1, \"x\": 0")))!;
            Assert.That(ex.Errors.Count, Is.EqualTo(2));
            Assert.That(ex.Message, Does.EndWith("(and 1 more)"));
        }

        [Test]
        public void Documents_built_in_code_are_validated_with_paths_too()
        {
            var doc = new SceneDocument();
            doc.Bodies.Add(new SceneBody { Name = "b", Shape = new SceneSphere { Radius = 1 }, Mass = 0 });
            doc.Generators.Add(new SceneTower { Count = 0 });
            Assert.That(SceneValidator.Validate(doc).Select(e => e.ToString()).ToList(), Is.EqualTo(new[]
            {
                "$.bodies[0].mass: must be > 0, got 0",
                "$.generators[0].count: must be >= 1, got 0",
            }));
        }
    }
}
