using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    /// <summary>A body's <c>lockAxes</c> in the scene format: reading, writing, errors with paths, building.</summary>
    public class LockAxesSceneTests
    {
        static string Scene(string extra, string type = "dynamic") => $@"{{
  ""format"": ""fulcrum-scene/1"",
  ""bodies"": [
    {{ ""name"": ""ground"", ""type"": ""static"", ""shape"": {{ ""type"": ""box"", ""halfExtents"": [5, 0.5, 5] }}, ""position"": [0, -0.5, 0] }},
    {{ ""name"": ""b"", ""type"": ""{type}"", ""shape"": {{ ""type"": ""box"", ""halfExtents"": [0.5, 0.5, 0.5] }},
      ""position"": [0, 2, 0], ""velocity"": [1, 0, 2]{extra} }}
  ]
}}";

        static List<string> Errors(string text) => SceneFile.Check(text, out _).Select(e => $"{e.Path}: {e.Message}").ToList();

        [Test]
        public void Lock_axes_are_read_built_and_written_back()
        {
            SceneDocument doc = SceneFile.Parse(Scene(@", ""lockAxes"": [""linearZ"", ""angularX"", ""angularY""]"));
            Assert.That(doc.Bodies[1].LockAxes, Is.EqualTo(AxisLocks.LinearZ | AxisLocks.AngularX | AxisLocks.AngularY));
            Assert.That(doc.Bodies[0].LockAxes, Is.EqualTo(AxisLocks.None), "absent: none");

            SceneInstance scene = SceneBuilder.Build(doc);
            BodyHandle b = scene.GetBody("b");
            Assert.That(scene.World.GetAxisLocks(b), Is.EqualTo(AxisLocks.LinearZ | AxisLocks.AngularX | AxisLocks.AngularY));
            Assert.That(scene.World.GetBody(b).LinearVelocity, Is.EqualTo(new Vector3(1, 0, 0)), "the locked z part of the velocity is dropped");
            for (int n = 0; n < 30; n++) scene.World.Step(1f / 60f);
            Assert.That(scene.World.GetBody(b).Position.Z, Is.EqualTo(0f));

            string text = SceneFile.Save(doc);
            Assert.That(text, Does.Contain("\"lockAxes\""));
            Assert.That(SceneFile.Parse(text).Bodies[1].LockAxes, Is.EqualTo(doc.Bodies[1].LockAxes));
            Assert.That(SceneFile.Save(SceneFile.Parse(Scene(""))), Does.Not.Contain("lockAxes"), "no locks, no field: files without it are unchanged");
        }

        [Test]
        public void Bad_lock_axes_are_errors_with_the_path_of_the_item()
        {
            Assert.That(Errors(Scene(@", ""lockAxes"": [""linearY"", ""sideways""]")),
                Has.Some.StartsWith("$.bodies[1].lockAxes[1]: unknown axis 'sideways'"));
            Assert.That(Errors(Scene(@", ""lockAxes"": [""linearY"", ""linearY""]")),
                Has.Some.StartsWith("$.bodies[1].lockAxes[1]: axis 'linearY' is listed twice"));
            Assert.That(Errors(Scene(@", ""lockAxes"": [3]")),
                Has.Some.StartsWith("$.bodies[1].lockAxes[0]: expected an axis name"));
            Assert.That(Errors(Scene(@", ""lockAxes"": ""linearY""")),
                Has.Some.StartsWith("$.bodies[1].lockAxes: expected an array"));
            Assert.That(Errors(Scene(@", ""lockAxes"": [""linearY""]", type: "kinematic")),
                Has.Some.StartsWith("$.bodies[1].lockAxes: a kinematic body is not moved by the solver"));
            Assert.That(Errors(Scene(@", ""lockAxes"": []")), Is.Empty, "an empty list is no locks");
        }

        [Test]
        public void The_validator_rejects_unknown_bits_in_a_document_built_in_code()
        {
            SceneDocument doc = SceneFile.Parse(Scene(""));
            doc.Bodies[1].LockAxes = (AxisLocks)64;
            Assert.That(SceneValidator.Validate(doc).Select(e => e.Path), Has.Member("$.bodies[1].lockAxes"));
        }
    }
}
