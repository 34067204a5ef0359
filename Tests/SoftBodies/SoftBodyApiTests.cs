using System;
using System.Linq;
using System.Numerics;
using Fulcrum.Mathematics;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    public class SoftBodyApiTests
    {
        static SoftBodyDef JellyCube() => SoftBodyScenes.Cube(0.4f, 2, MaterialPresets.Jelly, new Vector3(0, 1, 0));

        [Test]
        public void A_world_without_soft_bodies_does_not_need_the_soft_body_assembly()
        {
            Assert.That(typeof(World).Assembly.GetReferencedAssemblies().Select(a => a.Name), Has.No.Member("Fulcrum.SoftBodies"));
            var world = new World();
            Assert.That(world.SoftBodyStage, Is.Null);
            world.Step(SoftBodyScenes.Dt);
            world.CreateSoftBody(JellyCube());
            Assert.That(world.SoftBodyStage, Is.InstanceOf<SoftBodySystem>());
        }

        [Test]
        public void Handles_are_generation_checked()
        {
            var world = new World();
            SoftBodyHandle a = world.CreateSoftBody(JellyCube());
            Assert.That(world.IsValid(a), Is.True);
            world.DestroySoftBody(a);
            Assert.That(world.IsValid(a), Is.False);
            Assert.Throws<StaleHandleException>(() => world.GetSoftBody(a));
            Assert.Throws<StaleHandleException>(() => world.DestroySoftBody(a));
            SoftBodyHandle b = world.CreateSoftBody(JellyCube());
            Assert.That(b.Index, Is.EqualTo(a.Index), "the slot is reused");
            Assert.That(b, Is.Not.EqualTo(a));
            Assert.Throws<StaleHandleException>(() => world.GetSoftBody(a));
            Assert.That(world.GetSoftBody(b).Handle, Is.EqualTo(b));
            Assert.Throws<StaleHandleException>(() => new World().GetSoftBody(b));
            Assert.Throws<StaleHandleException>(() => world.GetSoftBody(SoftBodyHandle.None));
        }

        [Test]
        public void A_rejected_def_after_a_removal_leaves_the_freed_slot_to_the_next_body()
        {
            var world = new World();
            SoftBodyHandle a = world.CreateSoftBody(JellyCube());
            SoftBodyHandle b = world.CreateSoftBody(JellyCube());
            world.DestroySoftBody(a);
            BodyHandle gone = world.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            world.DestroyBody(gone);
            SoftBodyDef bad = JellyCube();
            bad.Pins = new[] { SoftPin.ToBody(new Vector3(-1), new Vector3(1), gone) };
            Assert.Throws<StaleHandleException>(() => world.CreateSoftBody(bad));

            SoftBodySystem system = SoftBodySystem.Of(world)!;
            Assert.That(system.Count, Is.EqualTo(1), "the rejected body took no slot");
            SoftBodyHandle c = world.CreateSoftBody(JellyCube());
            Assert.That(c.Index, Is.EqualTo(a.Index), "the freed slot is still the next one");
            Assert.That(c.Generation, Is.GreaterThan(a.Generation));
            Assert.That(world.IsValid(a), Is.False);
            Assert.That(() => world.GetSoftBody(a), Throws.TypeOf<StaleHandleException>().With.Message.Contains("does not name a live soft body"));
            Assert.That(system[0].Handle, Is.EqualTo(b), "the removal swapped the last body into the first place");
            Assert.That(system[1].Handle, Is.EqualTo(c));
            Assert.That(() => system[2], Throws.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(() => system[-1], Throws.TypeOf<ArgumentOutOfRangeException>());
        }

        // Two worlds whose soft-body slots have the same generations and liveness but step their
        // bodies in other orders: a restore takes the saved order, and both runs go on alike.
        [Test]
        public void A_restore_takes_the_saved_stepping_order_of_reused_slots()
        {
            static SoftBodyDef Cube(float x) => SoftBodyScenes.Cube(0.4f, 2, MaterialPresets.Jelly, new Vector3(x, 1, 0));
            World Build(bool firstFreedFirst)
            {
                var world = new World();
                BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
                world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0)));
                SoftBodyHandle s0 = world.CreateSoftBody(Cube(0)), s1 = world.CreateSoftBody(Cube(0.3f));
                world.DestroySoftBody(firstFreedFirst ? s0 : s1);
                world.DestroySoftBody(firstFreedFirst ? s1 : s0);
                world.CreateSoftBody(Cube(0));
                world.CreateSoftBody(Cube(0.3f));
                return world;
            }
            World a = Build(true), b = Build(false);
            SoftBodySystem sa = SoftBodySystem.Of(a)!, sb = SoftBodySystem.Of(b)!;
            Assert.That(sa[0].Handle.Index, Is.EqualTo(1), "slot 1 was freed last, so taken first");
            Assert.That(sb[0].Handle.Index, Is.EqualTo(0));
            SoftBodyScenes.Run(a, 10);

            b.RestoreState(new System.IO.MemoryStream(State.StateRoundTripTests.Save(a)));
            Assert.That(sb[0].Handle, Is.EqualTo(sa[0].Handle));
            Assert.That(sb[1].Handle, Is.EqualTo(sa[1].Handle));
            SoftBodyScenes.Run(a, 10);
            SoftBodyScenes.Run(b, 10);
            for (int k = 0; k < 2; k++)
                Assert.That(sb[k].Positions.ToArray(), Is.EqualTo(sa[k].Positions.ToArray()), $"body {k}");
            Assert.That(State.StateRoundTripTests.Save(b), Is.EqualTo(State.StateRoundTripTests.Save(a)));
        }

        static void AssertRejected(SoftBodyDef def, string field, string? message = null)
        {
            var world = new World();
            var ex = Assert.Throws<ArgumentException>(() => world.CreateSoftBody(def));
            Assert.That(ex!.ParamName, Is.EqualTo(field));
            if (message != null) Assert.That(ex.Message, Does.Contain(message));
            Assert.That(world.SoftBodyStage, Is.Null, "nothing changed");
        }

        [Test]
        public void Bad_material_fields_are_named()
        {
            SoftBodyDef def = JellyCube();
            def.Material.PoissonRatio = 0.5f;
            AssertRejected(def, "material.PoissonRatio");
            def = JellyCube();
            def.Material.YoungsModulus = 0f;
            AssertRejected(def, "material.YoungsModulus");
            def = JellyCube();
            def.Material.Density = -1f;
            AssertRejected(def, "material.Density");
        }

        [Test]
        public void Pins_that_select_no_vertex_are_rejected()
        {
            SoftBodyDef def = JellyCube();
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-1, 0.25f, -1), new Vector3(1, 0.3f, 1)) };
            AssertRejected(def, "softBody.Pins[0]", "selects no vertex");
        }

        [Test]
        public void Other_bad_fields_are_named()
        {
            SoftBodyDef def = JellyCube();
            def.Mesh = null;
            AssertRejected(def, "softBody.Mesh");
            def = JellyCube();
            def.Position = new Vector3(float.NaN, 0, 0);
            AssertRejected(def, "softBody.Position");
            def = JellyCube();
            def.InitialDeformation = Mat3.Diagonal(new Vector3(1, 0, 1));
            AssertRejected(def, "softBody.InitialDeformation");
            def = JellyCube();
            def.Probes = new[] { new Vector3(3, 0, 0) };
            AssertRejected(def, "softBody.Probes[0]", "outside");
            def = JellyCube();
            def.Iterations = 0;
            AssertRejected(def, "softBody.Iterations");
        }

        [Test]
        public void Pin_to_a_destroyed_body_is_a_stale_handle()
        {
            var world = new World();
            BodyHandle body = world.CreateBody(BodyDef.Dynamic(Vector3.Zero));
            world.DestroyBody(body);
            SoftBodyDef def = JellyCube();
            def.Pins = new[] { SoftPin.ToBody(new Vector3(-1), new Vector3(1), body) };
            Assert.Throws<StaleHandleException>(() => world.CreateSoftBody(def));
        }

        [Test]
        public void Probes_follow_the_material_by_barycentric_interpolation()
        {
            var world = SoftBodyScenes.ZeroGravityWorld();
            SoftBodyDef def = JellyCube();
            def.Probes = new[] { new Vector3(0.05f, 0.1f, -0.13f), new Vector3(0, 0.2f, 0) };
            def.InitialDeformation = Mat3.FromRows(new Vector3(1.1f, 0.2f, 0), new Vector3(0, 0.9f, 0), new Vector3(0.1f, 0, 1.2f));
            def.Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.5f);
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            for (int i = 0; i < 2; i++)
            {
                Vector3 expected = def.Position + Vector3.Transform(def.InitialDeformation * def.Probes[i], def.Rotation);
                Assert.That((body.GetProbe(i) - expected).Length(), Is.LessThan(1e-5f), $"probe {i}: an affine map is reproduced exactly");
            }
            Assert.Throws<ArgumentOutOfRangeException>(() => body.GetProbe(2));
        }

        [Test]
        public void Pinned_vertices_do_not_move_and_diagnostics_report_the_soft_trace()
        {
            var world = new World();
            SoftBodyDef def = JellyCube();
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-1, 0.2f, -1), new Vector3(1, 0.2f, 1)) };
            SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
            Vector3[] start = body.Positions.ToArray();
            SoftBodyScenes.Run(world, 60);
            int pinned = 0;
            for (int i = 0; i < body.VertexCount; i++)
            {
                if (body.InverseMasses[i] != 0) continue;
                pinned++;
                Assert.That(body.Positions[i], Is.EqualTo(start[i]));
            }
            Assert.That(pinned, Is.EqualTo(9));
            SoftBodyStats s = body.ComputeStats();
            Assert.That(s.Centroid.Y, Is.LessThan(1f), "hangs below its pins");
            Assert.That(s.StrainEnergy, Is.GreaterThan(0f));
            var colors = new Vector3[body.VertexCount];
            body.ComputeStrainColors(colors, 0.1f);
            foreach (Vector3 c in colors) Assert.That(c.X + c.Y + c.Z, Is.InRange(0.99f, 1.01f));
            var energies = new float[body.ElementCount];
            body.ComputeElementEnergy(energies);
            Assert.That(energies.Sum(), Is.EqualTo(s.StrainEnergy).Within(1e-3f * s.StrainEnergy));
        }

        [Test]
        public void Threads_give_bit_identical_results()
        {
            Vector3[] Run(int threads)
            {
                var settings = WorldSettings.Default;
                settings.Threads = threads;
                var world = new World(settings);
                BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
                world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0)));
                SoftBodyDef def = SoftBodyScenes.Cube(0.5f, 8, MaterialPresets.Jelly, new Vector3(0, 0.3f, 0));
                def.LinearVelocity = new Vector3(0.5f, 0, 0.2f);
                SoftBody body = world.GetSoftBody(world.CreateSoftBody(def));
                SoftBodyScenes.Run(world, 20);
                return body.Positions.ToArray();
            }
            Vector3[] one = Run(1), three = Run(3);
            for (int i = 0; i < one.Length; i++) Assert.That(three[i], Is.EqualTo(one[i]), $"vertex {i}");
        }

        [Test]
        public void A_steady_step_allocates_nothing()
        {
            var world = new World();
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0)));
            BodyHandle ball = world.CreateBody(BodyDef.Static(new Vector3(2, 0.3f, 0)));
            world.AddShape(ball, ShapeDef.Of(ShapeGeometry.Sphere(0.3f)));
            BodyHandle box = world.CreateBody(BodyDef.Dynamic(new Vector3(0, 0.55f, 0)));
            world.AddShape(box, ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.1f))));
            SoftBodyDef jelly = SoftBodyScenes.Cube(0.4f, 4, MaterialPresets.Jelly, new Vector3(0, 0.21f, 0));
            jelly.SelfCollision = true;
            jelly.Plasticity = SoftPlasticity.Flow(0.05f, 1f);
            jelly.Pins = new[] { SoftPin.ToBody(new Vector3(-1, 0.2f, -1), new Vector3(1, 0.2f, 1), box) };
            world.CreateSoftBody(jelly);
            SoftBodyDef cloth = SoftBodyDef.Of(SoftMesh.Cloth(1f, 1f, 10, 10), MaterialPresets.Cloth, new Vector3(2, 0.7f, 0));
            world.CreateSoftBody(cloth);
            // Warm-up: the JIT's tier-up and the amortised growth of contact buffers happen here.
            SoftBodyScenes.Run(world, 90);
            // The first read of the counter in a method has been seen to count 24 bytes of its own.
            long before = GC.GetAllocatedBytesForCurrentThread();
            long empty = GC.GetAllocatedBytesForCurrentThread() - before;
            before = GC.GetAllocatedBytesForCurrentThread();
            SoftBodyScenes.Run(world, 30);
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            TestContext.Out.WriteLine($"empty window {empty} bytes, 30 steps {allocated} bytes");
            Assert.That(allocated, Is.EqualTo(0));
        }

        [Test]
        public void Plasticity_keeps_a_dent_where_an_elastic_blob_springs_back()
        {
            float Dent(bool plastic)
            {
                World world = SoftBodyScenes.WorldWithGround();
                // Stiff enough (1e5 Pa) that its own weight strains it ~1.5%, far below the 8% yield.
                var material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e5f, 0.45f, 1000f);
                SoftBodyDef def = SoftBodyScenes.Cube(0.3f, 5, material, new Vector3(0, 0.151f, 0));
                def.Probes = new[] { new Vector3(0, 0.15f, 0) };
                if (plastic) def.Plasticity = SoftPlasticity.Flow(0.08f, 5f);
                SoftBody blob = world.GetSoftBody(world.CreateSoftBody(def));
                BodyHandle press = world.CreateBody(BodyDef.Kinematic(new Vector3(0, 0.41f, 0)));
                world.AddShape(press, ShapeDef.Of(ShapeGeometry.Sphere(0.1f)));
                SoftBodyScenes.Run(world, 60);
                float rest = blob.GetProbe(0).Y;
                for (int i = 0; i < 120; i++)
                {
                    // Touches the top at y = 0.405; down 5 cm into it over 0.5 s, hold 0.5 s, lift away.
                    float t = i * SoftBodyScenes.Dt;
                    float y = t < 0.5f ? 0.405f - 0.05f * t / 0.5f : t < 1f ? 0.355f : 0.355f + 0.5f * (t - 1f);
                    world.SetKinematicTarget(press, new Vector3(0, y, 0), Quaternion.Identity);
                    world.Step(SoftBodyScenes.Dt);
                }
                SoftBodyScenes.Run(world, 60);
                return rest - blob.GetProbe(0).Y;
            }
            float elastic = Dent(false), plastic = Dent(true);
            TestContext.Out.WriteLine($"dent after release: elastic {elastic * 1000:F1} mm, plastic {plastic * 1000:F1} mm");
            Assert.That(elastic, Is.LessThan(0.003f), "springs back");
            Assert.That(plastic, Is.InRange(0.01f, 0.05f), "keeps a dent, no deeper than the press went");
        }
    }
}
