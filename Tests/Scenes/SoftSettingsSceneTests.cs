using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    /// <summary>A soft body's solver and contact settings in the scene format: reading, writing, errors, building.</summary>
    public class SoftSettingsSceneTests
    {
        const string AllSettings = @", ""rotation"": [0, 0.38268343, 0, 0.9238795], ""velocity"": [1.5, -2, 0.25],
""substeps"": 12, ""iterations"": 3, ""dampingTime"": 0.002, ""linearDamping"": 0.1, ""gravityScale"": 0.5,
""friction"": 0.3, ""collisionRadius"": 0.004, ""collideWithShapes"": false, ""collideWithSoftBodies"": false,
""selfCollision"": true, ""layer"": 2, ""collidesWith"": [0, 2, 5]";

        static string Scene(string extra = "") => $@"{{
  ""format"": ""fulcrum-scene/1"",
  ""softBodies"": [
    {{ ""name"": ""s"", ""mesh"": {{ ""type"": ""box"", ""size"": [1, 1, 1], ""cells"": [2, 2, 2] }},
      ""material"": {{ ""youngsModulus"": 1e5, ""poissonRatio"": 0.3, ""density"": 500 }}, ""position"": [1, 2, 3]{extra} }}
  ]
}}";

        static List<string> Errors(string text) => SceneFile.Check(text, out _).Select(e => $"{e.Path}: {e.Message}").ToList();

        [Test]
        public void Every_setting_is_read_with_its_value()
        {
            SceneSoftBody s = SceneFile.Parse(Scene(AllSettings)).SoftBodies[0];
            Assert.That(s.Rotation, Is.EqualTo(new Quaternion(0, 0.38268343f, 0, 0.9238795f)));
            Assert.That(s.Velocity, Is.EqualTo(new Vector3(1.5f, -2, 0.25f)));
            Assert.That((s.Substeps, s.Iterations), Is.EqualTo(((int?)12, (int?)3)));
            Assert.That((s.DampingTime, s.LinearDamping, s.GravityScale), Is.EqualTo(((float?)0.002f, (float?)0.1f, (float?)0.5f)));
            Assert.That((s.Friction, s.CollisionRadius), Is.EqualTo(((float?)0.3f, (float?)0.004f)));
            Assert.That((s.CollideWithShapes, s.CollideWithSoftBodies, s.SelfCollision), Is.EqualTo(((bool?)false, (bool?)false, (bool?)true)));
            Assert.That(s.Layer, Is.EqualTo(2));
            Assert.That(s.CollidesWith, Is.EqualTo(new[] { 0, 2, 5 }));
        }

        [Test]
        public void Every_setting_round_trips_exactly_and_omitted_ones_stay_omitted()
        {
            SceneDocument doc = SceneFile.Parse(Scene(AllSettings));
            string saved = SceneFile.Save(doc);
            Assert.That(SceneDifference.Find(doc, SceneFile.Parse(saved)), Is.Null);
            Assert.That(SceneFile.Save(SceneFile.Parse(saved)), Is.EqualTo(saved));
            foreach (string key in new[] { "rotation", "velocity", "substeps", "iterations", "dampingTime", "linearDamping", "gravityScale",
                                           "friction", "collisionRadius", "collideWithShapes", "collideWithSoftBodies", "selfCollision", "layer", "collidesWith" })
                Assert.That(saved, Does.Contain($"\"{key}\""), key);

            string saved0 = SceneFile.Save(SceneFile.Parse(Scene()));
            string plain = saved0.Substring(saved0.IndexOf("\"softBodies\"", System.StringComparison.Ordinal));
            foreach (string key in new[] { "rotation", "velocity", "substeps", "dampingTime", "friction", "collisionRadius", "layer", "collidesWith" })
                Assert.That(plain, Does.Not.Contain($"\"{key}\""), key);
        }

        [Test]
        public void An_empty_collidesWith_round_trips_as_no_layer()
        {
            SceneDocument doc = SceneFile.Parse(Scene(", \"collidesWith\": []"));
            Assert.That(doc.SoftBodies[0].CollidesWith, Is.Empty);
            Assert.That(SceneFile.Parse(SceneFile.Save(doc)).SoftBodies[0].CollidesWith, Is.Empty);
        }

        [TestCase("\"substeps\": -1", "$.softBodies[0].substeps: must be in [0, 1000], got -1")]
        [TestCase("\"substeps\": 1001", "$.softBodies[0].substeps: must be in [0, 1000], got 1001")]
        [TestCase("\"substeps\": 2.5", "$.softBodies[0].substeps: expected an integer, got 2.5")]
        [TestCase("\"iterations\": 0", "$.softBodies[0].iterations: must be in [1, 1000], got 0")]
        [TestCase("\"iterations\": \"4\"", "$.softBodies[0].iterations: expected an integer, got \"4\"")]
        [TestCase("\"dampingTime\": -0.01", "$.softBodies[0].dampingTime: must be >= 0, got -0.01")]
        [TestCase("\"dampingTime\": 1e39", "$.softBodies[0].dampingTime: 1e39 is out of the range of a float")]
        [TestCase("\"dampingTime\": true", "$.softBodies[0].dampingTime: expected a number, got true")]
        [TestCase("\"linearDamping\": -1", "$.softBodies[0].linearDamping: must be >= 0, got -1")]
        [TestCase("\"gravityScale\": [1]", "$.softBodies[0].gravityScale: expected a number, got an array of 1")]
        [TestCase("\"friction\": -0.1", "$.softBodies[0].friction: must be >= 0, got -0.1")]
        [TestCase("\"collisionRadius\": -0.001", "$.softBodies[0].collisionRadius: must be >= 0, got -0.001")]
        [TestCase("\"collideWithShapes\": 1", "$.softBodies[0].collideWithShapes: expected true or false, got 1")]
        [TestCase("\"collideWithSoftBodies\": \"yes\"", "$.softBodies[0].collideWithSoftBodies: expected true or false, got \"yes\"")]
        [TestCase("\"selfCollision\": 0", "$.softBodies[0].selfCollision: expected true or false, got 0")]
        [TestCase("\"layer\": 32", "$.softBodies[0].layer: must be in [0, 31], got 32")]
        [TestCase("\"layer\": -1", "$.softBodies[0].layer: must be in [0, 31], got -1")]
        [TestCase("\"collidesWith\": [0, 40]", "$.softBodies[0].collidesWith[1]: must be in [0, 31], got 40")]
        [TestCase("\"collidesWith\": 3", "$.softBodies[0].collidesWith: expected an array of integers, got 3")]
        [TestCase("\"rotation\": [0, 0, 0, 0]", "$.softBodies[0].rotation: must be a non-zero quaternion [x, y, z, w]")]
        [TestCase("\"velocity\": [0, 1e39, 0]", "$.softBodies[0].velocity[1]: 1e39 is out of the range of a float")]
        public void A_bad_setting_is_one_error_at_its_path(string field, string expected)
        {
            Assert.That(Errors(Scene(", " + field)), Is.EqualTo(new[] { expected }));
        }

        [Test]
        public void A_NaN_setting_set_in_code_is_an_error_at_its_path()
        {
            SceneDocument doc = SceneFile.Parse(Scene());
            doc.SoftBodies[0].DampingTime = float.NaN;
            doc.SoftBodies[0].Friction = float.PositiveInfinity;
            doc.SoftBodies[0].GravityScale = float.NaN;
            Assert.That(SceneValidator.Validate(doc).Select(e => e.Path),
                Is.EqualTo(new[] { "$.softBodies[0].dampingTime", "$.softBodies[0].gravityScale", "$.softBodies[0].friction" }));
        }

        [Test]
        public void The_settings_reach_the_soft_body_definition()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(Scene(AllSettings)));
            SoftBodyDef def = SceneSoftBodyBuilder.Definition(scene, 0);
            Assert.That((def.Substeps, def.Iterations), Is.EqualTo((12, 3)));
            Assert.That((def.DampingTime, def.LinearDamping, def.GravityScale), Is.EqualTo((0.002f, 0.1f, 0.5f)));
            Assert.That((def.Friction, def.CollisionRadius), Is.EqualTo((0.3f, 0.004f)));
            Assert.That((def.CollideWithShapes, def.CollideWithSoftBodies, def.SelfCollision), Is.EqualTo((false, false, true)));
            Assert.That(def.Layer, Is.EqualTo(2));
            Assert.That(def.CollidesWith, Is.EqualTo(0b100101u));
            Assert.That(def.LinearVelocity, Is.EqualTo(new Vector3(1.5f, -2, 0.25f)));
            Assert.That(Quaternion.Dot(def.Rotation, new Quaternion(0, 0.38268343f, 0, 0.9238795f)), Is.EqualTo(1f).Within(1e-6f));
        }

        [Test]
        public void Omitted_settings_keep_the_engine_defaults()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(Scene()));
            SoftBodyDef def = SceneSoftBodyBuilder.Definition(scene, 0), d = SoftBodyDef.Default;
            Assert.That((def.Substeps, def.Iterations, def.DampingTime, def.LinearDamping, def.GravityScale),
                Is.EqualTo((d.Substeps, d.Iterations, d.DampingTime, d.LinearDamping, d.GravityScale)));
            Assert.That((def.Friction, def.CollisionRadius, def.CollideWithShapes, def.CollideWithSoftBodies, def.SelfCollision, def.Layer, def.CollidesWith),
                Is.EqualTo((d.Friction, d.CollisionRadius, d.CollideWithShapes, d.CollideWithSoftBodies, d.SelfCollision, d.Layer, d.CollidesWith)));
            Assert.That(def.Rotation, Is.EqualTo(Quaternion.Identity));
        }

        [Test]
        public void Runner_substeps_and_iterations_override_the_scene_file()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(Scene(", \"substeps\": 12, \"iterations\": 3")));
            SoftBody body = scene.World.GetSoftBody(SceneSoftBodyBuilder.Build(scene, substeps: 5, iterations: 2)[0]);
            Assert.That((body.Substeps, body.Iterations), Is.EqualTo((5, 2)));
            SceneInstance kept = SceneBuilder.Build(SceneFile.Parse(Scene(", \"substeps\": 12, \"iterations\": 3")));
            SoftBody own = kept.World.GetSoftBody(SceneSoftBodyBuilder.Build(kept)[0]);
            Assert.That((own.Substeps, own.Iterations), Is.EqualTo((12, 3)));
        }

        [Test]
        public void A_rotated_box_is_turned_about_its_centre_at_the_position()
        {
            SceneInstance scene = SceneBuilder.Build(SceneFile.Parse(Scene(", \"rotation\": [0, 0, 0.38268343, 0.9238795]")));
            SoftBody body = scene.World.GetSoftBody(SceneSoftBodyBuilder.Build(scene)[0]);
            Vector3 min = new Vector3(float.MaxValue), max = new Vector3(float.MinValue);
            foreach (Vector3 p in body.Positions) { min = Vector3.Min(min, p); max = Vector3.Max(max, p); }
            // A unit cube turned 45 degrees about z spans sqrt(2) in x and y, 1 in z, centred on the position.
            Vector3 span = max - min, centre = (min + max) / 2;
            Assert.That(span.X, Is.EqualTo(1.4142135f).Within(1e-5f));
            Assert.That(span.Y, Is.EqualTo(1.4142135f).Within(1e-5f));
            Assert.That(span.Z, Is.EqualTo(1f).Within(1e-5f));
            Assert.That(Vector3.Distance(centre, new Vector3(1, 2, 3)), Is.LessThan(1e-5f));
        }
    }
}
