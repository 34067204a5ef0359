using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using Fulcrum.Dynamics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.RigidScenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Architecture
{
    /// <summary>
    /// Guards code moves that must not change results: every scene of Samples~/Scenes is stepped
    /// a fixed number of times and two hashes of the world are compared with the ones stored in
    /// Tests/Architecture/step-hashes.txt. The hashes are the .NET 10 build's: Unity's build has
    /// no SIMD paths and rounds differently, so this test is .NET-only. "state" hashes the bytes of <see cref="World.SaveState"/>
    /// (everything a step reads, internal layouts included); "motion" hashes what a layout change
    /// leaves alone: body poses and velocities, contact manifolds with their impulses, joint
    /// reports (force, torque, error, broken) and the soft bodies' state. A change of a saved
    /// struct's layout (JointData, say) moves "state" only; any change of results moves both.
    /// To regenerate the file after a change whose effect is understood, run the tests with
    /// FULCRUM_WRITE_STEP_HASHES=1 (it rewrites Tests/Architecture/step-hashes.txt in the source
    /// tree and passes), then say in the commit why the hashes moved.
    /// </summary>
    public class StepHashTests
    {
        const int RigidSteps = 150;
        const int SoftSteps = 20;
        const string FileName = "step-hashes.txt";

        static string SourceFile()
        {
            for (var d = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); d != null; d = d.Parent)
            {
                string candidate = Path.Combine(d.FullName, "Tests", "Architecture", FileName);
                if (File.Exists(Path.Combine(d.FullName, "package.json"))) return candidate;
            }
            throw new AssertionException("package.json not found above the test directory");
        }

        static IEnumerable<string> SceneNames()
        {
            return Directory.GetFiles(RigidSceneFiles.ScenesDirectory, "*.json")
                .Select(p => Path.GetFileNameWithoutExtension(p))
                .OrderBy(n => n, StringComparer.Ordinal);
        }

        /// <summary>Runs one scene and returns its "state" and "motion" hashes as hex.</summary>
        static (string State, string Motion) Hash(string name)
        {
            SceneInstance scene = RigidSceneFiles.Build(name);
            bool soft = scene.SoftBodies.Count > 0;
            if (soft) SceneSoftBodyBuilder.Build(scene, directory: RigidSceneFiles.ScenesDirectory);
            int steps = soft ? SoftSteps : RigidSteps;
            for (int n = 0; n < steps; n++) scene.World.Step(scene.Timestep);

            var stream = new MemoryStream();
            scene.World.SaveState(stream);
            ulong state = StateLayout.Fnv1a(stream.ToArray());
            return (state.ToString("x16"), Motion(scene.World).ToString("x16"));
        }

        static ulong Motion(World world)
        {
            var w = new StateWriter();
            BodyStorage b = world.Bodies;
            for (int k = 0; k < b.ActiveCount; k++)
            {
                int i = b.Active[k];
                w.Write(i);
                w.Write(b.Position[i]);
                w.Write(b.Rotation[i]);
                w.Write(b.LinearVelocity[i]);
                w.Write(b.AngularVelocity[i]);
                w.Write(b.Awake[i]);
            }
            for (int k = 0; k < world.Contacts.ManifoldCount; k++) w.Write(world.Contacts.Pool[world.Contacts.Source[k]]);
            JointStorage j = world.Joints;
            for (int k = 0; k < j.ActiveCount; k++)
            {
                ref JointData d = ref j.Data[j.Active[k]];
                w.Write(j.Active[k]);
                w.Write(d.Force);
                w.Write(d.Torque);
                w.Write(d.Error);
                w.Write(d.Broken);
            }
            if (world.SoftBodyStage is IStateStage stage && stage.HasState) stage.SaveState(w);
            return StateLayout.Fnv1a(w.Written);
        }

        [Test]
        public void Every_sample_scene_steps_to_the_stored_hashes()
        {
            var lines = new List<string>();
            foreach (string name in SceneNames())
            {
                (string state, string motion) = Hash(name);
                lines.Add(name + " " + state + " " + motion);
            }

            string path = SourceFile();
            if (Environment.GetEnvironmentVariable("FULCRUM_WRITE_STEP_HASHES") == "1")
            {
                var text = new StringBuilder();
                text.Append("# scene state-hash motion-hash, written by StepHashTests (FULCRUM_WRITE_STEP_HASHES=1); ")
                    .Append(RigidSteps).Append(" steps, soft scenes ").Append(SoftSteps).Append('\n');
                foreach (string line in lines) text.Append(line).Append('\n');
                File.WriteAllText(path, text.ToString());
                return;
            }

            Assert.That(File.Exists(path), Is.True, "no stored hashes: run once with FULCRUM_WRITE_STEP_HASHES=1");
            List<string> expected = File.ReadAllLines(path).Where(l => l.Length > 0 && l[0] != '#').ToList();
            var differing = new List<string>();
            foreach (string line in lines)
                if (!expected.Contains(line)) differing.Add(line);
            Assert.That(lines.Count, Is.EqualTo(expected.Count), "scene count");
            Assert.That(differing, Is.Empty, "scenes whose hashes moved (name state motion)");
        }
    }
}
