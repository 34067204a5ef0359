using System;
using System.IO;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.Runner;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.Viewer
{
    /// <summary>The .frec recorder of the runner (Documentation~/RecordingFormat.md) and its C# reader.</summary>
    public class RecorderTests
    {
        // One of every shape kind, a joint to the world, a soft cube, all touching something.
        static World MixedWorld(out BodyHandle box, out SoftBodyHandle jelly)
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)) with { Name = "ground" });
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(10, 0.5f, 10))));
            BodyHandle plane = world.CreateBody(BodyDef.Static(default) with { Name = "floor" });
            world.AddShape(plane, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, -2)));
            BodyHandle ramp = world.CreateBody(BodyDef.Static(new Vector3(4, 0, 0)) with { Name = "ramp" });
            world.AddShape(ramp, ShapeDef.Of(ShapeGeometry.TriangleMesh(TriangleMesh.Create(
                new[] { new Vector3(-1, 0, -1), new Vector3(1, 0, -1), new Vector3(1, 1, 1), new Vector3(-1, 1, 1) },
                new[] { 0, 2, 1, 0, 3, 2 }))));
            box = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.5f, 0)) with { Name = "box" });
            world.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            BodyHandle ball = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 1.6f, 0)) with { Name = "ball" });
            ShapeDef offset = ShapeDef.Of(ShapeGeometry.Sphere(0.3f));
            offset.LocalPose = new Pose(new Vector3(0.1f, 0, 0), Quaternion.Identity);
            world.AddShape(ball, offset);
            BodyHandle pill = world.CreateBody(BodyDef.Dynamic(new Vector3(2, 0.5f, 0)) with { Name = "pill" });
            world.AddShape(pill, ShapeDef.Of(ShapeGeometry.Capsule(0.2f, 0.3f)));
            BodyHandle rock = world.CreateBody(BodyDef.Dynamic(new Vector3(-2, 0.5f, 0)) with { Name = "rock" });
            world.AddShape(rock, ShapeDef.Of(ShapeGeometry.ConvexHull(new[]
            {
                new Vector3(-0.4f, -0.4f, -0.4f), new Vector3(0.4f, -0.4f, -0.4f), new Vector3(0, -0.4f, 0.4f), new Vector3(0, 0.4f, 0),
            })));
            world.CreateJoint(JointDef.Ball(pill, default, new Vector3(0, 0.5f, 0), new Vector3(2, 1.2f, 0)));
            jelly = world.CreateSoftBody(SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.4f), 2, 2, 2), MaterialPresets.Jelly, new Vector3(-4, 0.3f, 0)));
            return world;
        }

        [Test]
        public void A_recording_reads_back_with_every_shape_joint_soft_body_and_frame()
        {
            World world = MixedWorld(out BodyHandle box, out SoftBodyHandle jelly);
            var memory = new MemoryStream();
            Vector3 boxAt = default;
            using (var recorder = new Recorder(world, 1f / 60, memory, ownsStream: false))
            {
                recorder.Record(0);
                for (int n = 1; n <= 30; n++)
                {
                    world.Step(1f / 60);
                    recorder.Record(n);
                }
                boxAt = world.GetBody(box).Position;
                Assert.That(recorder.FrameCount, Is.EqualTo(31));
                Assert.That(recorder.BytesWritten, Is.EqualTo(memory.Length));
            }

            Recording rec = Recording.Read(memory.ToArray());
            Assert.That(rec.Version, Is.EqualTo(RecordingFormat.Version));
            Assert.That(rec.Timestep, Is.EqualTo(1f / 60));
            Assert.That(rec.Gravity, Is.EqualTo(world.Gravity));
            Assert.That(rec.Bodies.ConvertAll(b => b.Name), Is.EqualTo(new[] { "ground", "floor", "ramp", "box", "ball", "pill", "rock" }));
            Assert.That(rec.Bodies[3].Type, Is.EqualTo(BodyType.Dynamic));
            Assert.That(rec.Bodies[3].Mass, Is.EqualTo(world.GetBody(box).Mass));
            Assert.That(rec.Shapes.ConvertAll(s => s.Type), Is.EqualTo(new[]
                { ShapeType.Box, ShapeType.Plane, ShapeType.TriangleMesh, ShapeType.Box, ShapeType.Sphere, ShapeType.Capsule, ShapeType.ConvexHull }));
            Assert.That(rec.Shapes[0].Size, Is.EqualTo(new Vector3(10, 0.5f, 10)));
            Assert.That(rec.Shapes[1].Offset, Is.EqualTo(-2f));
            Assert.That(rec.Shapes[2].Indices, Has.Length.EqualTo(6));
            Assert.That(rec.Shapes[4].Position, Is.EqualTo(new Vector3(0.1f, 0, 0)));
            Assert.That(rec.Shapes[5].Size, Is.EqualTo(new Vector3(0.2f, 0.3f, 0)));
            Assert.That(rec.Shapes[6].Vertices, Has.Length.EqualTo(4));
            Assert.That(rec.Shapes[6].Faces, Has.Length.EqualTo(4));
            Assert.That(rec.Shapes[6].Faces, Has.All.Length.EqualTo(3));
            Assert.That(rec.Joints, Has.Count.EqualTo(1));
            Assert.That(rec.Joints[0].Kind, Is.EqualTo(JointKind.Ball));
            Assert.That(rec.Joints[0].BodyA, Is.EqualTo(5));
            Assert.That(rec.Joints[0].BodyB, Is.EqualTo(-1));
            SoftBody soft = world.GetSoftBody(jelly);
            Assert.That(rec.SoftBodies, Has.Count.EqualTo(1));
            Assert.That(rec.SoftBodies[0].VertexCount, Is.EqualTo(soft.VertexCount));
            Assert.That(rec.SoftBodies[0].VerticesPerElement, Is.EqualTo(4));
            Assert.That(rec.SoftBodies[0].Elements.Length, Is.EqualTo(4 * soft.ElementCount));
            Assert.That(rec.SoftBodies[0].Surface, Is.Not.Empty);

            Assert.That(rec.Frames, Has.Count.EqualTo(31));
            Recording.Frame last = rec.Frames[30];
            Assert.That(last.Step, Is.EqualTo(30));
            Assert.That(last.Time, Is.EqualTo(world.Time));
            Assert.That(last.Positions[3], Is.EqualTo(boxAt));
            Assert.That(last.Profile[RecordingFormat.ProfileEntries - 1], Is.GreaterThan(0f), "the step's total time");
            Assert.That(last.Contacts, Is.Not.Empty);
            Assert.That(last.Contacts, Has.Some.Matches<Recording.Contact>(c => c.NormalImpulse > 0 && (c.BodyA == 3 || c.BodyB == 3)));
            Assert.That(Vector3.Distance(last.Joints[0].AnchorA, last.Joints[0].AnchorB), Is.LessThan(0.05f));
            Assert.That(last.Joints[0].Error, Is.GreaterThanOrEqualTo(0f));
            Assert.That(last.SoftPositions[0], Is.EqualTo(soft.Positions.ToArray()));
            var j = new float[soft.ElementCount];
            soft.ComputeElementJ(j);
            Assert.That(last.SoftElementJ[0], Is.EqualTo(j));
            Assert.That(rec.Frames[0].SoftElementStrain[0], Has.All.LessThan(1e-5f), "no strain at rest");
            Assert.That(last.SoftElementStrain[0], Has.Length.EqualTo(soft.ElementCount));
            Assert.That(last.SoftEnergy, Is.GreaterThan(0f));
            Assert.That(rec.Frames[0].Positions[4].Y, Is.EqualTo(1.6f), "frame 0 is the state before the first step");
        }

        [Test]
        public void Element_strain_of_a_10_percent_stretch_is_0_105_in_every_element_of_tets_and_shells()
        {
            foreach (SoftMesh mesh in new[] { SoftMesh.Box(new Vector3(1, 0.5f, 0.7f), 3, 2, 2), SoftMesh.Cloth(1, 1, 3, 3) })
            {
                var strain = new ElementStrain(mesh);
                Vector3[] x = mesh.Vertices.ToArray();
                var rotation = Quaternion.CreateFromYawPitchRoll(0.3f, 0.2f, 0.1f);
                for (int i = 0; i < x.Length; i++) x[i] = Vector3.Transform(new Vector3(1.1f * x[i].X, x[i].Y, x[i].Z), rotation) + new Vector3(5, 0, 0);
                int elements = mesh.IsShell ? mesh.TriangleCount : mesh.TetrahedronCount;
                var e = new float[elements];
                strain.Compute(x, e);
                // E_xx = (1.1^2 - 1) / 2, the other components 0; a rotation and a shift change nothing.
                Assert.That(e, Has.All.EqualTo(0.105f).Within(1e-4f), mesh.IsShell ? "shell" : "tets");
                strain.Compute(mesh.Vertices, e);
                Assert.That(e, Has.All.EqualTo(0f).Within(1e-6f));
            }
        }

        [Test]
        public void A_body_that_falls_asleep_is_flagged()
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(5, 0.5f, 5))));
            BodyHandle box = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.5f, 0)));
            world.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            var memory = new MemoryStream();
            using (var recorder = new Recorder(world, 1f / 60, memory, ownsStream: false))
            {
                recorder.Record(0);
                for (int n = 1; n <= 240; n++) world.Step(1f / 60);
                Assert.That(world.GetBody(box).IsAwake, Is.False);
                recorder.Record(240);
            }
            Recording rec = Recording.Read(memory.ToArray());
            Assert.That(rec.Frames[0].BodyFlags[1] & RecordingFormat.BodyAsleep, Is.EqualTo(0));
            Assert.That(rec.Frames[1].BodyFlags[1] & RecordingFormat.BodyAsleep, Is.EqualTo(RecordingFormat.BodyAsleep));
            Assert.That(rec.Bodies[1].Name, Is.EqualTo("#1"), "an unnamed body gets its slot");
        }

        [Test]
        public void A_removed_body_is_flagged_and_a_body_in_its_slot_is_not_taken_for_it()
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(5, 0.5f, 5))));
            BodyHandle first = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.5f, 0)));
            world.AddShape(first, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            var memory = new MemoryStream();
            using (var recorder = new Recorder(world, 1f / 60, memory, ownsStream: false))
            {
                world.DestroyBody(first);
                BodyHandle second = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.5f, 0)));
                world.AddShape(second, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
                Assert.That(second.Index, Is.EqualTo(first.Index), "the new body reuses the slot");
                world.Step(1f / 60);
                recorder.Record(1);
            }
            Recording.Frame frame = Recording.Read(memory.ToArray()).Frames[0];
            Assert.That(frame.BodyFlags[1] & RecordingFormat.BodyRemoved, Is.EqualTo(RecordingFormat.BodyRemoved));
            Assert.That(frame.Contacts, Is.Not.Empty);
            Assert.That(frame.Contacts, Has.All.Matches<Recording.Contact>(c => c.BodyA != 1 && c.BodyB != 1));
        }

        [Test]
        public void Recording_switched_off_writes_nothing_and_allocates_nothing()
        {
            World world = MixedWorld(out _, out _);
            var memory = new MemoryStream();
            using var recorder = new Recorder(world, 1f / 60, memory, ownsStream: false) { Enabled = false };
            long header = memory.Length;
            long allocated = 0;
            for (int n = 1; n <= 100; n++)
            {
                world.Step(1f / 60);
                long before = GC.GetAllocatedBytesForCurrentThread();
                recorder.Record(n);
                allocated += GC.GetAllocatedBytesForCurrentThread() - before;
            }
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(memory.Length, Is.EqualTo(header));
            Assert.That(recorder.FrameCount, Is.EqualTo(0));
        }

        [Test]
        public void Recording_allocates_nothing_per_step_once_warm()
        {
            World world = MixedWorld(out _, out _);
            // A stream with room for every frame, so that only the recorder could allocate.
            var memory = new MemoryStream(32 << 20);
            using var recorder = new Recorder(world, 1f / 60, memory, ownsStream: false);
            for (int n = 1; n <= 30; n++)
            {
                world.Step(1f / 60);
                recorder.Record(n);
            }
            long allocated = 0;
            for (int n = 31; n <= 130; n++)
            {
                world.Step(1f / 60);
                long before = GC.GetAllocatedBytesForCurrentThread();
                recorder.Record(n);
                allocated += GC.GetAllocatedBytesForCurrentThread() - before;
            }
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(recorder.FrameCount, Is.EqualTo(130));
        }

        [Test]
        public void A_cut_header_is_refused_with_a_reason_and_a_cut_last_frame_is_left_out()
        {
            World world = MixedWorld(out _, out _);
            var memory = new MemoryStream();
            long header;
            using (var recorder = new Recorder(world, 1f / 60, memory, ownsStream: false))
            {
                header = memory.Length;
                recorder.Record(0);
                world.Step(1f / 60);
                recorder.Record(1);
            }
            byte[] data = memory.ToArray();
            Recording cut = Recording.Read(data[..(data.Length - 3)]);
            Assert.That(cut.Truncated, Is.True);
            Assert.That(cut.Frames, Has.Count.EqualTo(1), "a frame cut short is left out");
            Assert.That(Recording.Read(data).Truncated, Is.False);
            Assert.That(() => Recording.Read(data[..(int)(header - 3)]), Throws.InstanceOf<InvalidDataException>().With.Message.Contains("ends early"));
            data[0] = (byte)'X';
            Assert.That(() => Recording.Read(data), Throws.InstanceOf<InvalidDataException>().With.Message.Contains("FREC"));
        }
    }
}
