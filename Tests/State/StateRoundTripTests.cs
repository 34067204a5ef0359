using System;
using System.IO;
using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.RigidScenes;
using NUnit.Framework;

namespace Fulcrum.Tests.State
{
    /// <summary>
    /// World.SaveState / RestoreState (issue 11, item 5): saving, restoring and stepping on is bit
    /// for bit what never stopping gives, for rigid, jointed, meshed, sleeping and soft scenes,
    /// restored into the same world, a world built from the same scene, or a fresh one.
    /// </summary>
    public partial class StateRoundTripTests
    {
        internal static byte[] Save(World w)
        {
            var s = new MemoryStream();
            w.SaveState(s);
            return s.ToArray();
        }

        internal static void Restore(World w, byte[] state) => w.RestoreState(new MemoryStream(state));

        // The highest dynamic body slot (in the pyramid: a box resting on others).
        static BodyHandle LastDynamicBody(World w)
        {
            for (int i = w.Bodies.SlotCount - 1; i >= 0; i--)
                if (w.Bodies.ActiveIndex[i] >= 0 && w.Bodies.Type[i] == BodyType.Dynamic) return new BodyHandle(i, w.Bodies.Generation[i], w.Id);
            throw new AssertionException("no dynamic body");
        }

        static SceneInstance BuildScene(string name)
        {
            SceneInstance scene = RigidSceneFiles.Build(name);
            if (scene.Document.SoftBodies.Count > 0) SceneSoftBodyBuilder.Build(scene, directory: RigidSceneFiles.ScenesDirectory);
            return scene;
        }

        // Steps before the save, steps after it: enough for contacts, warm starts, sleep timers
        // and (for pyramid and dominoes) sleeping islands to be live state at the save.
        [TestCase("pyramid", 120, 60)]
        [TestCase("pile", 90, 60)]
        [TestCase("dominoes", 150, 90)]
        [TestCase("ragdolls", 60, 60)]
        [TestCase("chain", 60, 60)]
        [TestCase("bridge", 60, 60)]
        [TestCase("jelly-on-mesh-ramp", 40, 40)]
        [TestCase("box-on-jelly", 40, 40)]
        [TestCase("jelly-stack", 30, 30)]
        [TestCase("pinned-flag", 30, 30)]
        [TestCase("slime-plastic", 40, 30)]
        public void Restoring_into_the_same_scene_continues_bit_identically(string name, int before, int after)
        {
            SceneInstance a = BuildScene(name);
            RigidSceneFiles.Run(a, before);
            byte[] state = Save(a.World);
            RigidSceneFiles.Run(a, after);

            SceneInstance b = BuildScene(name);
            Restore(b.World, state);
            Assert.That(Save(b.World), Is.EqualTo(state), "save, restore, save gives the same bytes");
            RigidSceneFiles.Run(b, after);

            Assert.That(b.World.StepIndex, Is.EqualTo(a.World.StepIndex));
            Assert.That(Save(b.World), Is.EqualTo(Save(a.World)), $"{name}: the whole state after {after} more steps");
        }

        [TestCase("pyramid")]
        [TestCase("ragdolls")]
        [TestCase("pile")]
        public void A_rigid_state_restores_into_a_fresh_world(string name)
        {
            SceneInstance a = BuildScene(name);
            RigidSceneFiles.Run(a, 45);
            byte[] state = Save(a.World);
            RigidSceneFiles.Run(a, 45);

            var fresh = new World();
            Restore(fresh, state);
            for (int n = 0; n < 45; n++) fresh.Step(a.Timestep);
            Assert.That(Save(fresh), Is.EqualTo(Save(a.World)));
            Assert.That(fresh.BodyCount, Is.EqualTo(a.World.BodyCount));
            Assert.That(fresh.Settings.Solver, Is.EqualTo(a.World.Settings.Solver));
        }

        [Test]
        public void Restoring_undoes_everything_done_since_the_save()
        {
            SceneInstance scene = BuildScene("pyramid");
            World w = scene.World;
            RigidSceneFiles.Run(scene, 30);
            BodyHandle kept = LastDynamicBody(w);
            byte[] state = Save(w);
            Vector3 at = w.GetBody(kept).Position;

            w.DestroyBody(kept);
            BodyHandle added = w.CreateBody(BodyDef.Dynamic(new Vector3(0, 20, 0)));
            w.AddShape(added, ShapeDef.Of(ShapeGeometry.Sphere(0.5f)));
            w.Gravity = new Vector3(0, 5, 0);
            RigidSceneFiles.Run(scene, 10);

            Restore(w, state);
            Assert.That(Save(w), Is.EqualTo(state));
            Assert.That(w.IsValid(kept), Is.True, "a handle from before the save names its body again");
            Assert.That(w.GetBody(kept).Position, Is.EqualTo(at));
            Assert.That(w.IsValid(added), Is.False, "a body created after the save is gone");
            Assert.That(w.Gravity.Y, Is.EqualTo(-9.81f).Within(1e-4f));
            Assert.That(w.ContactEvents.Length, Is.Zero);
        }

        [Test]
        public void Restoring_twice_from_one_state_gives_the_same_run()
        {
            SceneInstance scene = BuildScene("pile");
            RigidSceneFiles.Run(scene, 40);
            byte[] state = Save(scene.World);
            RigidSceneFiles.Run(scene, 30);
            byte[] first = Save(scene.World);
            Restore(scene.World, state);
            RigidSceneFiles.Run(scene, 30);
            Assert.That(Save(scene.World), Is.EqualTo(first));
        }

        [Test]
        public void Pending_end_events_of_removed_shapes_survive_a_restore()
        {
            SceneInstance scene = BuildScene("pyramid");
            World w = scene.World;
            RigidSceneFiles.Run(scene, 30);
            BodyHandle box = LastDynamicBody(w);
            w.DestroyBody(box);
            byte[] state = Save(w);

            w.Step(scene.Timestep);
            int ends = 0;
            foreach (var e in w.ContactEvents) if (e.Kind == Fulcrum.Collision.ContactEventKind.End) ends++;

            var fresh = new World();
            Restore(fresh, state);
            fresh.Step(scene.Timestep);
            int restoredEnds = 0;
            foreach (var e in fresh.ContactEvents)
            {
                if (e.Kind != Fulcrum.Collision.ContactEventKind.End) continue;
                restoredEnds++;
                Assert.That(e.BodyA.WorldId, Is.EqualTo(fresh.Id), "pending events carry the restoring world's handles");
            }
            Assert.That(ends, Is.GreaterThan(0));
            Assert.That(restoredEnds, Is.EqualTo(ends));
        }

        [Test]
        public void Meshes_sensors_kinematic_targets_and_fast_bodies_continue_bit_identically()
        {
            World Build()
            {
                var w = new World();
                var ground = TriangleMesh.Create(
                    new[] { new Vector3(-10, 0, -10), new Vector3(10, 0, -10), new Vector3(10, -1, 10), new Vector3(-10, -1, 10) },
                    new[] { 0, 2, 1, 0, 3, 2 });
                w.AddShape(w.CreateBody(BodyDef.Static(Vector3.Zero)), ShapeDef.Of(ShapeGeometry.TriangleMesh(ground)));
                var hull = ConvexHull.Create(new[] { new Vector3(0.3f, 0, 0), new Vector3(-0.3f, 0, 0), new Vector3(0, 0.4f, 0), new Vector3(0, 0, 0.3f), new Vector3(0, -0.2f, -0.3f) });
                for (int i = 0; i < 6; i++)
                {
                    BodyHandle b = w.CreateBody(BodyDef.Dynamic(new Vector3(i - 3, 1 + 0.3f * i, 0)));
                    w.AddShape(b, ShapeDef.Of(i % 2 == 0 ? ShapeGeometry.ConvexHull(hull) : ShapeGeometry.Capsule(0.2f, 0.3f)));
                }
                BodyDef fast = BodyDef.Dynamic(new Vector3(0, 3, -8));
                fast.LinearVelocity = new Vector3(0, -5, 120);
                fast.Ccd = true;
                w.AddShape(w.CreateBody(fast), ShapeDef.Of(ShapeGeometry.Sphere(0.05f)));
                BodyHandle paddle = w.CreateBody(BodyDef.Kinematic(new Vector3(0, 0.5f, 2)));
                w.AddShape(paddle, ShapeDef.Of(ShapeGeometry.Box(new Vector3(1, 0.1f, 0.3f))));
                BodyHandle trigger = w.CreateBody(BodyDef.Static(new Vector3(0, 0.5f, 0)));
                ShapeDef sensor = ShapeDef.Of(ShapeGeometry.Box(new Vector3(3, 1, 3)));
                sensor.IsSensor = true;
                w.AddShape(trigger, sensor);
                return w;
            }
            void Run(World w, int from, int count)
            {
                BodyHandle paddle = default;
                for (int i = 0; i < w.Bodies.SlotCount; i++)
                    if (w.Bodies.ActiveIndex[i] >= 0 && w.Bodies.Type[i] == BodyType.Kinematic) paddle = new BodyHandle(i, w.Bodies.Generation[i], w.Id);
                for (int n = from; n < from + count; n++)
                {
                    w.SetKinematicTarget(paddle, new Vector3(MathF.Sin(n * 0.05f), 0.5f, 2), Quaternion.CreateFromAxisAngle(Vector3.UnitY, n * 0.02f));
                    w.Step(1 / 60f);
                }
            }

            World a = Build();
            Run(a, 0, 50);
            byte[] state = Save(a);
            Run(a, 50, 50);
            World b = new World();
            Restore(b, state);
            Run(b, 50, 50);
            Assert.That(Save(b), Is.EqualTo(Save(a)));
        }
    }
}
