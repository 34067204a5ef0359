using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.Scenes;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    public class SceneRoundTripTests
    {
        static readonly string[] Samples = { SceneSamples.DesignExample, SceneSamples.Everything };

        [TestCaseSource(nameof(Samples))]
        public void Load_save_load_gives_an_equal_document_field_for_field(string text)
        {
            SceneDocument first = SceneFile.Parse(text);
            SceneDocument second = SceneFile.Parse(SceneFile.Save(first));
            Assert.That(SceneDifference.Find(first, second), Is.Null);
        }

        [TestCaseSource(nameof(Samples))]
        public void Saved_text_is_stable_when_saved_again(string text)
        {
            string saved = SceneFile.Save(SceneFile.Parse(text));
            Assert.That(SceneFile.Save(SceneFile.Parse(saved)), Is.EqualTo(saved));
        }

        [Test]
        public void The_verbatim_design_example_loads_with_the_mass_overriding_the_material_density()
        {
            SceneDocument doc = SceneFile.Parse(SceneSamples.DesignExampleVerbatim);
            Assert.That(doc.Bodies[1].Mass, Is.EqualTo(1f));
            Assert.That(SceneDifference.Find(doc, SceneFile.Parse(SceneFile.Save(doc))), Is.Null);
        }

        [Test]
        public void The_difference_finder_sees_a_one_ulp_change()
        {
            // Guards the round-trip tests against a comparer that cannot fail.
            SceneDocument a = SceneFile.Parse(SceneSamples.Everything);
            SceneDocument b = SceneFile.Parse(SceneSamples.Everything);
            Vector3 g = b.Gravity;
            // One ulp towards +infinity (MathF.BitIncrement, which .NET Standard 2.1 lacks): g.Y < 0.
            b.Gravity = new Vector3(g.X, System.BitConverter.Int32BitsToSingle(System.BitConverter.SingleToInt32Bits(g.Y) - 1), g.Z);
            Assert.That(SceneDifference.Find(a, b), Is.EqualTo("$.Gravity.y: -9.80665 vs -9.806649"));
        }

        [Test]
        public void Floats_read_exactly_as_the_nearest_float_to_the_text()
        {
            SceneDocument doc = SceneFile.Parse(SceneSamples.Everything);
            Assert.That(doc.Gravity, Is.EqualTo(new Vector3(0.1f, -9.80665f, 1e-7f)));
            Assert.That(doc.Timestep, Is.EqualTo(0.008333333f));
            Assert.That(doc.Bodies[2].AngularVelocity.Z, Is.EqualTo(123456.789f)); // within Limits.MaxInputSpeed
            float offset = ((ScenePlane)doc.Bodies[0].Shape!).Offset;
            Assert.That(System.BitConverter.SingleToInt32Bits(offset), Is.EqualTo(System.BitConverter.SingleToInt32Bits(-0f)), "-0 keeps its sign");
        }

        [Test]
        public void Every_field_of_the_everything_sample_is_read()
        {
            SceneDocument doc = SceneFile.Parse(SceneSamples.Everything);
            Assert.That(doc.Solver.Type, Is.EqualTo(SolverType.Pgs));
            Assert.That(doc.Solver.Iterations, Is.EqualTo(12));
            Assert.That(doc.Solver.Substeps, Is.EqualTo(3));
            Assert.That(doc.Materials.Count, Is.EqualTo(3));
            Assert.That(doc.FindMaterial("ice")!.Density, Is.Null);
            Assert.That(doc.FindMaterial("odd name")!.Restitution, Is.EqualTo(1f));
            Assert.That(doc.Bodies[1].Shape, Is.TypeOf<SceneMesh>());
            Assert.That(((SceneMesh)doc.Bodies[1].Shape!).Triangles, Is.EqualTo(new[] { 0, 1, 2 }));
            Assert.That(doc.Bodies[2].Ccd, Is.True);
            Assert.That(doc.Bodies[3].Type, Is.EqualTo(BodyType.Dynamic), "type defaults to dynamic");
            Assert.That(((SceneCompound)doc.Bodies[3].Shape!).Children.Count, Is.EqualTo(3));
            Assert.That(doc.Bodies[4].Type, Is.EqualTo(BodyType.Kinematic));
            var hinge = (SceneHingeJoint)doc.Joints[1];
            Assert.That(hinge.BodyB, Is.Null);
            Assert.That(hinge.LowerDeg, Is.EqualTo(-45f));
            Assert.That(hinge.MaxMotorTorque, Is.EqualTo(20f));
            Assert.That(hinge.BreakTorque, Is.EqualTo(50f));
            var distance = (SceneDistanceJoint)doc.Joints[2];
            Assert.That(distance.StiffnessHz, Is.EqualTo(4f));
            Assert.That(((SceneConeTwistJoint)doc.Joints[5]).TwistDeg, Is.EqualTo(10f));
            SceneSoftBody jelly = doc.SoftBodies[0];
            Assert.That(((SceneSoftBox)jelly.Mesh!).Cells, Is.EqualTo(new[] { 2, 3, 4 }));
            Assert.That(jelly.Material!.Model, Is.EqualTo(SceneSoftModel.NeoHookean));
            Assert.That(jelly.Material.Mu, Is.EqualTo(3000f));
            Assert.That(jelly.Pinned[0].To, Is.EqualTo("lift"));
            Assert.That(jelly.InitialDeformation, Is.EqualTo(Mat3.FromRows(new Vector3(1, 0.2f, 0), new Vector3(0, -1, 0), new Vector3(0, 0, 1))));
            Assert.That(doc.Generators.Count, Is.EqualTo(6));
            Assert.That(((ScenePile)doc.Generators[3]).Shape, Is.EqualTo(SceneShapeType.Capsule));
            Assert.That(((SceneChain)doc.Generators[4]).Anchor, Is.EqualTo(SceneChainAnchor.Both));
            Assert.That(((SceneDominoes)doc.Generators[5]).Axis, Is.EqualTo(SceneAxis.Z));
        }

        [Test]
        public void Saving_leaves_out_body_fields_at_their_defaults()
        {
            var doc = new SceneDocument();
            doc.Bodies.Add(new SceneBody { Name = "b", Shape = new SceneSphere { Radius = 1 } });
            string text = SceneFile.Save(doc);
            Assert.That(text, Does.Not.Contain("rotation").And.Not.Contain("velocity").And.Not.Contain("ccd"));
            Assert.That(text, Does.Contain("\"gravity\": [0, -9.81, 0]"));
        }
    }
}
