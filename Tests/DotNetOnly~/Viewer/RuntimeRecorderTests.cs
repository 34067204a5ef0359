using System;
using System.IO;
using System.Numerics;
using System.Linq;
using System.Threading;
using Fulcrum.Components;
using Fulcrum.Runner;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.Components;
using NUnit.Framework;

namespace Fulcrum.Tests.Viewer
{
    /// <summary>
    /// The runtime <see cref="Recorder"/> from the three ways in: the World API, a components
    /// <see cref="PhysicsScene"/> and the <see cref="PhysicsBridge"/> (with and without its physics
    /// thread), read back with the runner's C# reader.
    /// </summary>
    public class RuntimeRecorderTests
    {
        const float Dt = 1f / 60;

        // A five-box tower on a ground box and a jelly cube beside it.
        static World Tower()
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(10, 0.5f, 10))));
            for (int k = 0; k < 5; k++)
            {
                BodyHandle box = world.CreateBody(BodyDef.Dynamic(new Vector3(0.02f * k, 0.5f + k, 0)));
                world.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            }
            world.CreateSoftBody(SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.6f), 2, 2, 2), MaterialPresets.Jelly, new Vector3(3, 0.8f, 0)));
            return world;
        }

        static void AssertSameState(World a, World b)
        {
            BodyStorage x = a.Bodies, y = b.Bodies;
            for (int i = 0; i < x.SlotCount; i++)
            {
                Assert.That(y.Position[i], Is.EqualTo(x.Position[i]), "body " + i);
                Assert.That(y.Rotation[i], Is.EqualTo(x.Rotation[i]), "body " + i);
                Assert.That(y.LinearVelocity[i], Is.EqualTo(x.LinearVelocity[i]), "body " + i);
            }
            Assert.That(SoftBodySystem.Of(b)![0].Positions.ToArray(), Is.EqualTo(SoftBodySystem.Of(a)![0].Positions.ToArray()));
        }

        [Test]
        public void Recording_from_the_API_reads_back_and_leaves_the_run_bit_identical()
        {
            World plain = Tower(), recorded = Tower();
            var memory = new MemoryStream();
            using (var recorder = new Recorder(recorded, Dt, memory, ownsStream: false))
            {
                recorder.Record();
                for (int n = 1; n <= 90; n++)
                {
                    plain.Step(Dt);
                    recorded.Step(Dt);
                    recorder.Record();
                }
            }
            AssertSameState(plain, recorded);
            Recording rec = Recording.Read(memory.ToArray());
            Assert.That(rec.Frames, Has.Count.EqualTo(91));
            Assert.That(rec.Frames.ConvertAll(f => f.Step), Is.EqualTo(Enumerable.Range(0, 91).Select(i => (long)i).ToList()));
            Recording.Frame last = rec.Frames[90];
            for (int k = 0; k < 6; k++) Assert.That(last.Positions[k], Is.EqualTo(recorded.Bodies.Position[k]));
            Assert.That(last.SoftPositions[0], Is.EqualTo(SoftBodySystem.Of(recorded)![0].Positions.ToArray()));
            Assert.That(last.Time, Is.EqualTo(recorded.Time));
        }

        [Test]
        public void Contacts_of_a_sleeping_box_are_recorded_with_the_impulse_that_holds_it()
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Box(new Vector3(5, 0.5f, 5))));
            BodyHandle box = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.5f, 0)));
            world.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
            int steps = 0;
            while (world.GetBody(box).IsAwake && steps < 600)
            {
                world.Step(Dt);
                steps++;
            }
            Assert.That(world.GetBody(box).IsAwake, Is.False, "the box falls asleep");
            for (int n = 0; n < 5; n++) world.Step(Dt);
            var memory = new MemoryStream();
            using (var recorder = new Recorder(world, Dt, memory, ownsStream: false))
            {
                recorder.Record();
                recorder.SleepingContacts = true;
                recorder.Record();
            }
            Recording rec = Recording.Read(memory.ToArray());
            Assert.That(rec.Frames[0].Contacts, Is.Empty, "by default only the step's solved contacts");
            Recording.Frame frame = rec.Frames[1];
            Assert.That(frame.BodyFlags[1] & RecordingFormat.BodyAsleep, Is.EqualTo(RecordingFormat.BodyAsleep));
            Assert.That(frame.Contacts, Has.Length.EqualTo(4), "the four corners of the face it rests on");
            Assert.That(frame.Contacts, Has.All.Matches<Recording.Contact>(c => c.BodyA + c.BodyB == 1 && Math.Abs(c.Normal.Y) > 0.999f));
            // The impulse of the last solved step holds the box up: m g dt in all.
            float sum = 0;
            foreach (Recording.Contact c in frame.Contacts) sum += c.NormalImpulse;
            float weight = world.GetBody(box).Mass * 9.81f * Dt;
            Assert.That(sum, Is.EqualTo(weight).Within(0.02f * weight));
        }

        static PhysicsScene CrateScene()
        {
            var scene = new PhysicsScene(WorldSettings.Default, 0.02f);
            scene.CreateEntity("Ground", new Vector3(0, -0.5f, 0)).AddComponent<BoxCollider>().size = new Vector3(20, 1, 20);
            for (int k = 0; k < 3; k++)
            {
                Entity crate = scene.CreateEntity("Crate" + k, new Vector3(0, 0.6f + 1.05f * k, 0.01f * k));
                crate.AddComponent<Rigidbody>().mass = 2;
                crate.AddComponent<BoxCollider>();
            }
            return scene;
        }

        [Test]
        public void A_components_scene_records_every_fixed_step_with_entity_names_and_unchanged_results()
        {
            PhysicsScene plain = CrateScene(), recorded = CrateScene();
            var memory = new MemoryStream();
            Recorder recorder = recorded.StartRecording(memory);
            Assert.That(recorded.recorder, Is.SameAs(recorder));
            for (int f = 0; f < 40; f++)
            {
                plain.Tick(1f / 60);
                recorded.Tick(1f / 60);
            }
            recorded.StopRecording();
            Assert.That(recorded.recorder, Is.Null);
            for (int i = 0; i < plain.world.Bodies.SlotCount; i++)
                Assert.That(recorded.world.Bodies.Position[i], Is.EqualTo(plain.world.Bodies.Position[i]));

            Recording rec = Recording.Read(memory.ToArray());
            Assert.That(rec.Bodies.ConvertAll(b => b.Name), Is.EqualTo(new[] { "Ground", "Crate0", "Crate1", "Crate2" }));
            Assert.That(rec.Timestep, Is.EqualTo(0.02f));
            long steps = recorded.world.StepIndex;
            Assert.That(steps, Is.GreaterThan(30));
            Assert.That(rec.Frames, Has.Count.EqualTo(steps + 1), "frame 0, then one per fixed step");
            Assert.That(rec.Frames[^1].Step, Is.EqualTo(steps));
            Assert.That(rec.Frames[^1].Positions[3], Is.EqualTo(recorded.world.Bodies.Position[3]));
            Assert.That(rec.Frames[^1].Contacts, Is.Not.Empty);
        }

        [Test]
        public void A_components_scene_allocates_nothing_per_frame_recording_or_paused()
        {
            PhysicsScene scene = CrateScene();
            var memory = new MemoryStream(64 << 20);
            Recorder recorder = scene.StartRecording(memory);
            Assert.That(AllocationProbe.SteadyStateBytes(() => scene.Tick(0.02f)), Is.EqualTo(0), "recording");
            recorder.Enabled = false;
            long length = memory.Length;
            Assert.That(AllocationProbe.SteadyStateBytes(() => scene.Tick(0.02f)), Is.EqualTo(0), "paused");
            Assert.That(memory.Length, Is.EqualTo(length), "paused: nothing written");
            scene.StopRecording();
        }

        sealed class Ball : IPhysicsEntity
        {
            public Vector3 Position;
            public Quaternion Rotation = Quaternion.Identity;
            public void GetPose(out Vector3 position, out Quaternion rotation) { position = Position; rotation = Rotation; }
            public void SetPose(Vector3 position, Quaternion rotation) { Position = position; Rotation = rotation; }
        }

        static PhysicsBridge FallingBall(float threadHz, out ProxyHandle proxy)
        {
            PhysicsBridgeSettings s = PhysicsBridgeSettings.Default;
            s.FixedDt = 0.01f;
            s.ThreadRateHz = threadHz;
            var bridge = new PhysicsBridge(new World(), s);
            proxy = bridge.Register(new Ball { Position = new Vector3(0, 10, 0) }, BodyDef.Default, ShapeDef.Of(ShapeGeometry.Sphere(0.25f)));
            return bridge;
        }

        // Free fall with symplectic Euler: each step's second difference of height is -g dt^2
        // exactly (up to float rounding at y ~ 10). From rest at y = 10 in step 0 (when the
        // ball existed before the first step): y_n = 10 - g dt^2 n (n + 1) / 2.
        static void AssertFreeFall(Recording rec, float dt, bool fromStepZero)
        {
            long first = rec.Frames[0].Step;
            for (int f = 0; f < rec.Frames.Count; f++)
            {
                Recording.Frame frame = rec.Frames[f];
                Assert.That(frame.Step, Is.EqualTo(first + f), "one frame per step, none missed");
                if (f >= 2)
                {
                    float d2 = frame.Positions[0].Y - 2 * rec.Frames[f - 1].Positions[0].Y + rec.Frames[f - 2].Positions[0].Y;
                    Assert.That(d2, Is.EqualTo(-9.81f * dt * dt).Within(3e-5f), "step " + frame.Step);
                }
                long n = frame.Step;
                if (fromStepZero) Assert.That(frame.Positions[0].Y, Is.EqualTo(10 - 9.81f * dt * dt * n * (n + 1) / 2).Within(1e-4f * (1 + n)), "step " + n);
            }
        }

        [Test]
        public void The_bridge_records_on_the_callers_thread()
        {
            using PhysicsBridge bridge = FallingBall(0, out _);
            var memory = new MemoryStream();
            bridge.StartRecording(memory);
            Assert.That(bridge.IsRecording, Is.True);
            for (int f = 0; f < 20; f++) bridge.Step(0.02f);
            bridge.StopRecording();
            Recording rec = Recording.Read(memory.ToArray());
            Assert.That(rec.Frames, Has.Count.EqualTo(41));
            AssertFreeFall(rec, 0.01f, fromStepZero: true);
            Assert.That(() => bridge.StopRecording(), Throws.Nothing, "stopping twice is harmless");
        }

        [Test]
        public void The_bridge_records_on_its_physics_thread_and_stop_waits_for_the_last_frame()
        {
            using PhysicsBridge bridge = FallingBall(200, out _);
            var memory = new MemoryStream();
            bridge.StartRecording(memory);
            long start = bridge.ThreadSteps;
            var deadline = DateTime.UtcNow.AddSeconds(10);
            while (bridge.ThreadSteps < start + 30 && DateTime.UtcNow < deadline) Thread.Sleep(5);
            bridge.StopRecording();
            Assert.That(bridge.IsRecording, Is.False);
            Recording rec = Recording.Read(memory.ToArray());
            Assert.That(rec.Truncated, Is.False);
            Assert.That(rec.Frames, Has.Count.GreaterThanOrEqualTo(30));
            AssertFreeFall(rec, 1f / 200, fromStepZero: false);
            long length = memory.Length;
            Thread.Sleep(50);
            Assert.That(memory.Length, Is.EqualTo(length), "nothing written after StopRecording returned");
        }

        [Test]
        public void Disposing_a_threaded_bridge_closes_its_recording_whole()
        {
            var memory = new MemoryStream();
            var closed = new ClosingStream(memory);
            PhysicsBridge bridge = FallingBall(200, out _);
            bridge.StartRecording(closed, ownsStream: true);
            var deadline = DateTime.UtcNow.AddSeconds(10);
            while (bridge.ThreadSteps < 10 && DateTime.UtcNow < deadline) Thread.Sleep(5);
            bridge.Dispose();
            Assert.That(closed.Closed, Is.True, "the bridge owned the stream");
            Recording rec = Recording.Read(memory.ToArray());
            Assert.That(rec.Truncated, Is.False);
            Assert.That(rec.Frames, Has.Count.GreaterThanOrEqualTo(5));
            AssertFreeFall(rec, 1f / 200, fromStepZero: false);
        }

        // Keeps the bytes readable after the recorder closes it.
        sealed class ClosingStream : MemoryStream
        {
            readonly MemoryStream _into;
            public bool Closed;
            public ClosingStream(MemoryStream into) => _into = into;
            public override void Write(byte[] buffer, int offset, int count) => _into.Write(buffer, offset, count);
            public override void Write(ReadOnlySpan<byte> buffer) => _into.Write(buffer);
            protected override void Dispose(bool disposing) { Closed = true; base.Dispose(disposing); }
        }

        [Test]
        public void The_bridge_allocates_nothing_per_frame_while_recording()
        {
            using PhysicsBridge bridge = FallingBall(0, out _);
            var memory = new MemoryStream(64 << 20);
            bridge.StartRecording(memory);
            long bytes = AllocationProbe.SteadyStateBytes(() => { bridge.SyncFromGame(); bridge.Step(0.01f); bridge.SyncToGame(); });
            Assert.That(bytes, Is.EqualTo(0));
            bridge.StopRecording();
        }

        [Test]
        public void Bad_recording_calls_throw_and_change_nothing()
        {
            using PhysicsBridge bridge = FallingBall(0, out _);
            Assert.That(() => bridge.StartRecording(null!), Throws.ArgumentNullException);
            Assert.That(() => bridge.StartRecording(new MemoryStream(new byte[4], writable: false)), Throws.ArgumentException);
            Assert.That(bridge.IsRecording, Is.False);
            bridge.StartRecording(new MemoryStream());
            Assert.That(() => bridge.StartRecording(new MemoryStream()), Throws.InvalidOperationException);
            PhysicsScene scene = CrateScene();
            scene.StartRecording(new MemoryStream());
            Assert.That(() => scene.StartRecording(new MemoryStream()), Throws.InvalidOperationException);
            Assert.That(() => new Recorder(new World(), 0, new MemoryStream()), Throws.InstanceOf<ArgumentOutOfRangeException>());
        }
    }
}
