using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    /// <summary>Fields added to fulcrum-scene/1 (documented as extensions in Documentation~/SceneFormat.md).</summary>
    public class SceneExtensionTests
    {
        const string Stiff = @"{
  ""format"": ""fulcrum-scene/1"",
  ""solver"": { ""type"": ""tgs"", ""iterations"": 2, ""substeps"": 8, ""contactHertz"": 90, ""jointHertz"": 500, ""manifoldReuse"": 0.0005 },
  ""bodies"": [ { ""name"": ""ball"", ""shape"": { ""type"": ""sphere"", ""radius"": 0.5 }, ""position"": [0, 5, 0] } ]
}";

        const string Plastic = @"{
  ""format"": ""fulcrum-scene/1"",
  ""bodies"": [ { ""name"": ""ground"", ""type"": ""static"", ""shape"": { ""type"": ""box"", ""halfExtents"": [5, 0.5, 5] }, ""position"": [0, -0.5, 0] } ],
  ""softBodies"": [ { ""name"": ""slime"", ""mesh"": { ""type"": ""box"", ""size"": [0.3, 0.3, 0.3], ""cells"": [3, 3, 3] },
                    ""material"": { ""youngsModulus"": 1e3, ""poissonRatio"": 0.45, ""density"": 1050 },
                    ""position"": [0, 0.15, 0], ""plasticity"": { ""yieldStrain"": 0.02, ""flowRate"": 4 } } ]
}";

        [Test]
        public void Solver_stiffness_fields_reach_the_world_settings_and_round_trip()
        {
            SceneDocument doc = SceneFile.Parse(Stiff);
            SceneInstance scene = SceneBuilder.Build(doc);
            Assert.That(scene.World.Settings.ContactHertz, Is.EqualTo(90f));
            Assert.That(scene.World.Settings.JointHertz, Is.EqualTo(500f));
            Assert.That(scene.World.Settings.ManifoldReuseDistance, Is.EqualTo(0.0005f));
            Assert.That(SceneDifference.Find(doc, SceneFile.Parse(SceneFile.Save(doc))), Is.Null);
            Assert.That(SceneFile.Save(SceneFile.Parse(SceneSamples.OneBall())), Does.Not.Contain("Hertz"), "absent fields stay absent");
        }

        [Test]
        public void Shock_and_joint_correction_fields_reach_the_world_settings_round_trip_and_name_their_paths()
        {
            string text = Stiff.Replace("\"manifoldReuse\": 0.0005", "\"manifoldReuse\": 0.0005, \"shockPropagation\": false, \"shockDepth\": 0.004, \"jointTrees\": false, \"maxJointCorrectionSpeed\": 2.5");
            SceneDocument doc = SceneFile.Parse(text);
            WorldSettings s = SceneBuilder.Build(doc).World.Settings;
            Assert.That(s.ShockPropagation, Is.False);
            Assert.That(s.JointTrees, Is.False);
            Assert.That(s.ShockDepth, Is.EqualTo(0.004f));
            Assert.That(s.MaxJointCorrectionSpeed, Is.EqualTo(2.5f));
            SceneDocument again = SceneFile.Parse(SceneFile.Save(doc));
            Assert.That(again.Solver.ShockPropagation, Is.False);
            Assert.That(again.Solver.JointTrees, Is.False);
            Assert.That(again.Solver.ShockDepth, Is.EqualTo(0.004f));
            Assert.That(again.Solver.MaxJointCorrectionSpeed, Is.EqualTo(2.5f));
            Assert.That(SceneFile.Save(SceneFile.Parse(SceneSamples.OneBall())), Does.Not.Contain("shock").And.Not.Contain("jointTrees"), "absent fields stay absent");
            var e = Assert.Throws<SceneException>(() => SceneFile.Parse(text.Replace("\"shockDepth\": 0.004", "\"shockDepth\": -1")))!;
            Assert.That(e.Errors[0].Path, Is.EqualTo("$.solver.shockDepth"));
            e = Assert.Throws<SceneException>(() => SceneFile.Parse(text.Replace("\"maxJointCorrectionSpeed\": 2.5", "\"maxJointCorrectionSpeed\": 0")))!;
            Assert.That(e.Errors[0].Path, Is.EqualTo("$.solver.maxJointCorrectionSpeed"));
        }

        [Test]
        public void A_non_positive_joint_stiffness_names_its_path()
        {
            var e = Assert.Throws<SceneException>(() => SceneFile.Parse(Stiff.Replace("\"jointHertz\": 500", "\"jointHertz\": 0")))!;
            Assert.That(e.Errors[0].Path, Is.EqualTo("$.solver.jointHertz"));
        }

        [Test]
        public void A_negative_manifold_reuse_distance_names_its_path()
        {
            var e = Assert.Throws<SceneException>(() => SceneFile.Parse(Stiff.Replace("\"manifoldReuse\": 0.0005", "\"manifoldReuse\": -1")))!;
            Assert.That(e.Errors[0].Path, Is.EqualTo("$.solver.manifoldReuse"));
            Assert.That(SceneBuilder.Build(SceneFile.Parse(SceneSamples.OneBall())).World.Settings.ManifoldReuseDistance,
                Is.EqualTo(WorldSettings.Default.ManifoldReuseDistance), "absent: the default");
        }

        [Test]
        public void Soft_plasticity_reaches_the_soft_body_and_round_trips()
        {
            SceneDocument doc = SceneFile.Parse(Plastic);
            Assert.That(SceneDifference.Find(doc, SceneFile.Parse(SceneFile.Save(doc))), Is.Null);
            SceneInstance scene = SceneBuilder.Build(doc);
            SoftBodyHandle[] made = SceneSoftBodyBuilder.Build(scene);
            SoftPlasticity p = scene.World.GetSoftBody(made[0]).Plasticity;
            Assert.That((p.YieldStrain, p.FlowRate, p.MaxStrain), Is.EqualTo((0.02f, 4f, 1f)));
        }

        [Test]
        public void Plasticity_without_a_flow_rate_is_an_error_at_its_path()
        {
            var e = Assert.Throws<SceneException>(() => SceneFile.Parse(Plastic.Replace("\"flowRate\": 4", "\"maxStrain\": 2")))!;
            Assert.That(e.Errors[0].Path, Is.EqualTo("$.softBodies[0].plasticity.flowRate"));
        }
    }
}
