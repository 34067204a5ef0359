using System;
using System.IO;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using Fulcrum.Tests.RigidScenes;
using NUnit.Framework;

namespace Fulcrum.Tests.State
{
    /// <summary>
    /// A state that cannot be restored is refused with one clear <see cref="InvalidDataException"/>
    /// and the world is left exactly as it was (issue 11: bad input gets a clear error and nothing lost).
    /// </summary>
    public class StateErrorTests
    {
        static SceneInstance Scene(string name)
        {
            SceneInstance scene = RigidSceneFiles.Build(name);
            if (scene.Document.SoftBodies.Count > 0) SceneSoftBodyBuilder.Build(scene, directory: RigidSceneFiles.ScenesDirectory);
            return scene;
        }

        // Restoring <paramref name="state"/> into <paramref name="w"/> fails with a message
        // containing <paramref name="expected"/>, and changes nothing.
        static void AssertRefused(World w, byte[] state, string expected)
        {
            byte[] before = StateRoundTripTests.Save(w);
            var e = Assert.Throws<InvalidDataException>(() => StateRoundTripTests.Restore(w, state))!;
            Assert.That(e.Message, Does.Contain(expected));
            Assert.That(e.Message, Does.Not.Contain("\n"), "one line");
            Assert.That(StateRoundTripTests.Save(w), Is.EqualTo(before), "the world is unchanged");
        }

        static byte[] PyramidState()
        {
            SceneInstance s = Scene("pyramid");
            RigidSceneFiles.Run(s, 20);
            return StateRoundTripTests.Save(s.World);
        }

        static World Target()
        {
            SceneInstance s = Scene("ragdolls");
            RigidSceneFiles.Run(s, 5);
            return s.World;
        }

        [Test]
        public void A_truncated_state_is_refused()
        {
            byte[] state = PyramidState();
            AssertRefused(Target(), state.AsSpan(0, state.Length / 2).ToArray(), "ends early");
            AssertRefused(Target(), state.AsSpan(0, 10).ToArray(), "ends early");
            AssertRefused(Target(), Array.Empty<byte>(), "ends early");
        }

        [Test]
        public void A_damaged_state_is_refused_by_its_checksum()
        {
            byte[] state = PyramidState();
            state[state.Length / 2] ^= 0x10;
            AssertRefused(Target(), state, "checksum");
        }

        [Test]
        public void Something_else_than_a_state_is_refused()
        {
            AssertRefused(Target(), System.Text.Encoding.UTF8.GetBytes("{ \"bodies\": [] } and some more text to fill a header"), "Not a Fulcrum world state");
        }

        [Test]
        public void A_state_of_another_format_version_or_layout_is_refused()
        {
            byte[] state = PyramidState();
            byte[] version = (byte[])state.Clone();
            version[8] = 99;
            AssertRefused(Target(), version, "format 99 is not supported");
            byte[] layout = (byte[])state.Clone();
            layout[16] ^= 1;
            AssertRefused(Target(), layout, "layout differs");
        }

        [Test]
        public void A_state_whose_contents_do_not_hold_together_is_refused_with_the_byte_and_the_field()
        {
            byte[] state = PyramidState();
            // The payload starts after the 48-byte header with the "WRLD" tag; break the tag and
            // re-seal the checksum, as a bug in a writer would.
            state[48] = (byte)'X';
            long checksum = (long)StateLayout.Fnv1a(state.AsSpan(48));
            BitConverter.GetBytes(checksum).CopyTo(state, 40);
            AssertRefused(Target(), state, "expected section 'WRLD'");
        }

        [Test]
        public void Soft_bodies_must_exist_before_their_state_is_restored()
        {
            SceneInstance soft = Scene("jelly-on-mesh-ramp");
            RigidSceneFiles.Run(soft, 10);
            byte[] state = StateRoundTripTests.Save(soft.World);
            AssertRefused(new World(), state, "create the same soft bodies");
            AssertRefused(Target(), state, "create the same soft bodies");
            // A rigid state does not fit a world with soft bodies either.
            AssertRefused(Scene("jelly-on-mesh-ramp").World, PyramidState(), "holds no soft bodies");
            // Nor does another soft body.
            AssertRefused(Scene("pinned-flag").World, state, "soft bod");
        }

        [Test]
        public void Null_streams_and_calls_from_inside_a_step_are_refused()
        {
            World w = Target();
            Assert.Throws<ArgumentNullException>(() => w.SaveState(null!));
            Assert.Throws<ArgumentNullException>(() => w.RestoreState(null!));
            // A callback runs inside Step: restoring from there is refused.
            var probe = new CallbackProbe(Scene("pyramid").World, StateRoundTripTests.Save(w));
            probe.Run();
            Assert.That(probe.Called, Is.True);
            Assert.That(probe.Error, Is.Not.Null);
        }

        sealed class CallbackProbe
        {
            readonly World _world;
            readonly byte[] _state;
            public InvalidOperationException? Error;
            public bool Called;

            public CallbackProbe(World world, byte[] state)
            {
                _world = world;
                _state = state;
            }

            public void Run()
            {
                _world.Diverged += OnDiverged;
                // Force one divergence so that the callback runs inside Step.
                _world.Bodies.LinearVelocity[LastDynamic()] = new System.Numerics.Vector3(float.NaN, 0, 0);
                _world.Step(1 / 60f);
                _world.Diverged -= OnDiverged;
            }

            int LastDynamic()
            {
                for (int i = _world.Bodies.SlotCount - 1; i >= 0; i--)
                    if (_world.Bodies.ActiveIndex[i] >= 0 && _world.Bodies.Type[i] == BodyType.Dynamic) return i;
                return -1;
            }

            void OnDiverged(Divergence d)
            {
                Called = true;
                try { _world.RestoreState(new MemoryStream(_state)); }
                catch (InvalidOperationException e) { Error = e; }
            }
        }
    }
}
