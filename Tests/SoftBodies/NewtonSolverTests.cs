using System;
using System.Linq;
using System.Numerics;
using Fulcrum.Scenes;
using Fulcrum.SoftBodies;
using NUnit.Framework;

namespace Fulcrum.Tests.SoftBodies
{
    /// <summary>
    /// SoftSolver.Newton (issue 12, item 2): implicit Euler with Newton steps over the whole body
    /// reaches the converged answer of the mesh where XPBD is far too soft (the E = 1e9 Pa
    /// cantilever), matches the uniaxial closed form, keeps a nearly incompressible jelly's
    /// volume, allocates nothing per step, and is refused for shells.
    /// </summary>
    public class NewtonSolverTests
    {
        // The stiff-bar.json body: 1 x 0.1 x 0.1 m, 10 x 1 x 1 cells, E = 1e9 Pa, nu = 0.3, left end pinned.
        static readonly Vector3 BarSize = new Vector3(1, 0.1f, 0.1f);
        static NeoHookeanMaterial BarMaterial => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e9f, 0.3f, 1000f);

        // Mean downward displacement of the free end's vertices in the converged static state.
        static float ReferenceTipSag()
        {
            SoftMesh mesh = SoftMesh.Box(BarSize, 10, 1, 1);
            var eq = new StaticEquilibrium(mesh, BarMaterial);
            eq.AddGravity(new Vector3(0, -9.81f, 0));
            Vector3[] v = mesh.Vertices.ToArray();
            for (int i = 0; i < v.Length; i++) if (v[i].X < -0.499f) eq.Pin(i);
            Assert.That(eq.Solve(100), Is.True);
            float sag = 0;
            int n = 0;
            for (int i = 0; i < v.Length; i++)
                if (v[i].X > 0.499f) { sag += v[i].Y - eq.Position(i).Y; n++; }
            return sag / n;
        }

        static float SimulatedTipSag(SoftSolver solver, int steps)
        {
            World w = SoftBodyScenes.ZeroGravityWorld();
            w.Gravity = new Vector3(0, -9.81f, 0);
            SoftBodyDef def = SoftBodyDef.Of(SoftMesh.Box(BarSize, 10, 1, 1), BarMaterial, Vector3.Zero);
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-0.5f, -1, -1), new Vector3(-0.5f, 1, 1)) };
            def.Solver = solver;
            SoftBody bar = w.GetSoftBody(w.CreateSoftBody(def));
            Vector3[] rest = bar.Mesh.Vertices.ToArray();
            for (int s = 0; s < steps; s++) w.Step(1 / 60f);
            float sag = 0;
            int n = 0;
            for (int i = 0; i < rest.Length; i++)
                if (rest[i].X > 0.499f) { sag += rest[i].Y - bar.Positions[i].Y; n++; }
            return sag / n;
        }

        [Test]
        public void The_stiff_cantilever_reaches_its_converged_sag_at_the_default_settings()
        {
            float reference = ReferenceTipSag();
            float newton = SimulatedTipSag(SoftSolver.Newton, 120);
            float xpbd = SimulatedTipSag(SoftSolver.Xpbd, 120);
            TestContext.Out.WriteLine($"E = 1e9 cantilever tip sag: converged {reference * 1000:F4} mm, Newton {newton * 1000:F4} mm, XPBD {xpbd * 1000:F2} mm (defaults, 2 s)");
            Assert.That(reference, Is.EqualTo(0.000329f).Within(0.00002f), "the converged answer of this mesh");
            Assert.That(newton, Is.EqualTo(reference).Within(0.1f * reference), "within 10 % of the converged sag");
        }

        // A nearly incompressible bar pinned by one end, Newton at the defaults (one substep per
        // step: it touches nothing), hangs at the static sag of its mesh (StaticEquilibrium) and
        // no element inverts. The prediction x + v h + g h^2 moved the free vertices but not the
        // pinned ones and strained the tets between them far from the step's minimum; one
        // trust-region Newton step left most of it, and a classic Neo-Hookean capsule at
        // nu 0.4999 (soft fuzz seed 154) sagged to J = -9 within 11 steps. A held body now starts
        // its step from the substep's start when that has the lower G (StartFromPrevious).
        [TestCase(MaterialModel.NeoHookean, 0.4999f, 1e6f)]
        [TestCase(MaterialModel.NeoHookean, 0.4999f, 1.5e7f)]
        [TestCase(MaterialModel.StableNeoHookean, 0.4999f, 1.5e7f)]
        [TestCase(MaterialModel.NeoHookean, 0.49f, 1e6f)]
        public void A_nearly_incompressible_pinned_bar_hangs_at_its_static_sag(MaterialModel model, float nu, float youngsModulus)
        {
            var material = new NeoHookeanMaterial(model, youngsModulus, nu, 200f);
            SoftMesh mesh = SoftMesh.Box(BarSize, 10, 1, 1);
            var eq = new StaticEquilibrium(mesh, material);
            eq.AddGravity(new Vector3(0, -9.81f, 0));
            Vector3[] rest = mesh.Vertices.ToArray();
            for (int i = 0; i < rest.Length; i++) if (rest[i].X < -0.499f) eq.Pin(i);
            // The classic energy at nu 0.4999 stalls in round-off short of 1e-6 of the load; its
            // residual is then still below 1e-5 of the bar's weight.
            eq.Solve(400, 1e-6);
            double weight = 200.0 * BarSize.X * BarSize.Y * BarSize.Z * 9.81;
            TestContext.Out.WriteLine($"static reference: {eq.Iterations} Newton iterations, residual {eq.Residual:G3} N of {weight:G3} N");
            Assert.That(eq.Residual, Is.LessThan(1e-5 * weight), "the reference is converged");
            float reference = 0;
            int n = 0;
            for (int i = 0; i < rest.Length; i++)
                if (rest[i].X > 0.499f) { reference += rest[i].Y - eq.Position(i).Y; n++; }
            reference /= n;

            World w = SoftBodyScenes.ZeroGravityWorld();
            w.Gravity = new Vector3(0, -9.81f, 0);
            SoftBodyDef def = SoftBodyDef.Of(mesh, material, Vector3.Zero);
            def.Pins = new[] { SoftPin.ToWorld(new Vector3(-0.5f, -1, -1), new Vector3(-0.5f, 1, 1)) };
            def.Solver = SoftSolver.Newton;
            SoftBody bar = w.GetSoftBody(w.CreateSoftBody(def));
            float lowestJ = float.MaxValue;
            var j = new float[bar.ElementCount];
            for (int s = 0; s < 180; s++)
            {
                w.Step(1 / 60f);
                bar.ComputeElementJ(j);
                foreach (float x in j) lowestJ = MathF.Min(lowestJ, x);
            }
            float sag = 0;
            for (int i = 0; i < rest.Length; i++)
                if (rest[i].X > 0.499f) sag += rest[i].Y - bar.Positions[i].Y;
            sag /= n;
            TestContext.Out.WriteLine($"{model} nu {nu} E {youngsModulus:G2}: tip sag {sag * 1000:F3} mm after 3 s, static {reference * 1000:F3} mm; lowest J {lowestJ:F3}");
            Assert.That(SoftBodySystem.Of(w)!.DivergenceCount, Is.EqualTo(0));
            Assert.That(lowestJ, Is.GreaterThan(0.9f), "no element crushed or inverted");
            Assert.That(sag, Is.EqualTo(reference).Within(0.1f * reference), "at the static sag of the mesh");
        }

        [TestCase(MaterialModel.StableNeoHookean, 0.3f, 1.3f)]
        [TestCase(MaterialModel.NeoHookean, 0.3f, 1.3f)]
        [TestCase(MaterialModel.StableNeoHookean, 0.45f, 1.5f)]
        public void A_stretched_bar_matches_the_uniaxial_closed_form(MaterialModel model, float nu, float stretch)
        {
            SoftBody bar = UniaxialTests.StretchedBar(model, nu, stretch, 150, out _, SoftSolver.Newton);
            float a = (bar.GetProbe(1) - bar.GetProbe(0)).Length() / 0.2f;
            float by = (bar.GetProbe(3) - bar.GetProbe(2)).Length() / 0.2f;
            double expected = UniaxialTests.LateralStretch(model, bar.Material, a);
            TestContext.Out.WriteLine($"Newton {model} nu={nu}: axial {a:F4}, lateral {by:F4}, closed form {expected:F4}");
            Assert.That(a, Is.EqualTo(stretch).Within(0.05f * stretch));
            Assert.That(by, Is.EqualTo(expected).Within(0.002));
        }

        [TestCase(SoftSolver.Xpbd, 0.49f, 0.06f, 0.01f)]
        [TestCase(SoftSolver.Newton, 0.49f, 0.06f, 0.01f)]
        [TestCase(SoftSolver.Xpbd, 0.4999f, 0.02f, 0.005f)]
        [TestCase(SoftSolver.Newton, 0.4999f, 0.02f, 0.005f)]
        public void A_dropped_jelly_keeps_its_volume(SoftSolver solver, float nu, float duringImpact, float atRest)
        {
            World w = SoftBodyScenes.WorldWithGround();
            SoftBodyDef def = SoftBodyScenes.Cube(0.5f, 4, new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e4f, nu, 1030f), new Vector3(0, 1, 0));
            def.Solver = solver;
            SoftBody jelly = w.GetSoftBody(w.CreateSoftBody(def));
            float lowest = 1, highest = 1;
            for (int s = 0; s < 240; s++)
            {
                w.Step(1 / 60f);
                float ratio = jelly.ComputeStats().VolumeRatio;
                lowest = MathF.Min(lowest, ratio);
                highest = MathF.Max(highest, ratio);
            }
            float end = jelly.ComputeStats().VolumeRatio;
            TestContext.Out.WriteLine($"{solver} nu={nu}: volume ratio {lowest:F4}..{highest:F4} over the drop, {end:F4} at rest");
            Assert.That(1 - lowest, Is.LessThan(duringImpact), "volume lost at impact");
            Assert.That(highest - 1, Is.LessThan(duringImpact));
            Assert.That(MathF.Abs(end - 1), Is.LessThan(atRest), "volume at rest");
        }

        // A nearly incompressible Newton cube thrown at the ground. The contact pass after each
        // Newton step pushes the vertices that reached the ground out on their own; with linear
        // tets locking near nu = 0.5 one such pass stored 300 J of strain in a cube moving with
        // 86 J, the next steps released it, and every cube of nu 0.4999 (at 3 and 10 m/s) and of
        // nu 0.49 at 10 m/s blew apart (reported divergence, E 1e5-1e8 Pa). The energy guard
        // (SoftBody.GuardEnergy) takes any rise out of the motion about the centre of mass, so
        // the strain a push stores is not released as motion: measured, no divergence, min J at
        // least 0.15, the volume within 0.5 % at the end, and the motion's energy (kinetic and
        // gravitational) never above its start. The guard does not undo the strain; the
        // in-step springs to the ground keep the struck corner from being crushed (below).
        // With ground friction acting on Newton bodies (before, their springs to the ground left
        // the friction no normal impulse to act on: none at all), the throw down and across brakes
        // at the struck corner: min J 0.67 and 0.79, and 0.51 at nu 0.4999 and 10 m/s (an XPBD
        // cube in the same grid keeps 0.32-0.76). With friction patch by patch
        // (ShapeContactSolver.HoldPatch): 0.69, 0.79 and 0.62 (0.65, 0.79 and 0.59 before).
        [TestCase(0.49f, 10f, 0.6f)]
        [TestCase(0.4999f, 3f, 0.6f)]
        [TestCase(0.4999f, 10f, 0.45f)]
        public void A_nearly_incompressible_newton_cube_thrown_at_the_ground_never_gains_energy(float nu, float speed, float leastJ)
        {
            World w = SoftBodyScenes.WorldWithGround();
            var def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.2f), 4, 4, 4), new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e6f, nu, 1000f), new Vector3(0, 0.5f, 0));
            def.Solver = SoftSolver.Newton;
            def.LinearVelocity = Vector3.Normalize(new Vector3(1, -1, 0.3f)) * speed;
            def.Rotation = Quaternion.CreateFromYawPitchRoll(0.3f, 0.4f, 0.2f);
            SoftBody cube = w.GetSoftBody(w.CreateSoftBody(def));
            var j = new float[cube.ElementCount];
            double Total()
            {
                double e = 0;
                for (int i = 0; i < cube.VertexCount; i++)
                    e += cube.Masses[i] * (0.5 * cube.Velocities[i].LengthSquared() + 9.81 * cube.Positions[i].Y);
                return e;
            }
            double start = Total(), most = start;
            float minJ = 1;
            for (int n = 0; n < 120; n++)
            {
                w.Step(SoftBodyScenes.Dt);
                most = Math.Max(most, Total());
                cube.ComputeElementJ(j);
                foreach (float x in j) minJ = MathF.Min(minJ, x);
            }
            float volume = cube.ComputeStats().VolumeRatio;
            TestContext.Out.WriteLine($"Newton nu {nu}, thrown at {speed} m/s: motion's energy {start:F2} J at the start, at most {most:F2} J; min J {minJ:F3}, volume at the end {volume:F4}, diverged {SoftBodySystem.Of(w)!.DivergenceCount}");
            Assert.That(SoftBodySystem.Of(w)!.DivergenceCount, Is.EqualTo(0));
            // 0.15-0.23 before overlaps with immovable shapes were springs inside the Newton step
            // (the contact pass after it crushed the struck corner); 0.43-0.60 with them, while the
            // "held" penalty doubled the springs' stiffness along the normal; 0.72-0.82 with that
            // fixed and no friction; with friction, see the cases.
            Assert.That(minJ, Is.GreaterThan(leastJ), "the struck corner is not crushed");
            Assert.That(volume, Is.EqualTo(1f).Within(0.01f));
            Assert.That(most, Is.LessThanOrEqualTo(start + 1e-3 * Math.Abs(start)), "no energy from the contacts");
        }

        [Test]
        public void A_resting_newton_body_allocates_nothing_per_step()
        {
            World w = SoftBodyScenes.WorldWithGround();
            SoftBodyDef def = SoftBodyScenes.Cube(0.5f, 3, new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e6f, 0.3f, 1000f), new Vector3(0, 0.3f, 0));
            def.Solver = SoftSolver.Newton;
            w.CreateSoftBody(def);
            for (int s = 0; s < 60; s++) w.Step(1 / 60f);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int s = 0; s < 60; s++) w.Step(1 / 60f);
            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.Zero);
        }

        [Test]
        public void Newton_is_refused_for_shells_with_the_field_named()
        {
            SoftBodyDef cloth = SoftBodyDef.Of(SoftMesh.Cloth(1, 1, 4, 4), NeoHookeanMaterial.Default, Vector3.Zero);
            cloth.Solver = SoftSolver.Newton;
            var e = Assert.Throws<ArgumentException>(() => cloth.Validate())!;
            Assert.That(e.ParamName, Is.EqualTo("softBody.Solver"));

            cloth.Solver = SoftSolver.Xpbd;
            World w = SoftBodyScenes.ZeroGravityWorld();
            SoftBody shell = w.GetSoftBody(w.CreateSoftBody(cloth));
            Assert.Throws<InvalidOperationException>(() => shell.Solver = SoftSolver.Newton);
            Assert.That(shell.Solver, Is.EqualTo(SoftSolver.Xpbd));

            var cloth1 = SceneFile.Check(@"{ ""format"": ""fulcrum-scene/1"", ""softBodies"": [ { ""name"": ""flag"", ""solver"": ""newton"",
  ""mesh"": { ""type"": ""cloth"", ""size"": [1, 1], ""cells"": [4, 4] }, ""material"": { ""youngsModulus"": 1e6, ""poissonRatio"": 0.3, ""density"": 400 } } ] }", out _);
            Assert.That(cloth1.Select(x => x.ToString()), Has.Some.Contains("$.softBodies[0].solver"));
            var unknown = SceneFile.Check(@"{ ""format"": ""fulcrum-scene/1"", ""softBodies"": [ { ""name"": ""b"", ""solver"": ""fem"",
  ""mesh"": { ""type"": ""box"", ""size"": [1, 1, 1], ""cells"": [2, 2, 2] }, ""material"": { ""youngsModulus"": 1e6, ""poissonRatio"": 0.3, ""density"": 400 } } ] }", out _);
            Assert.That(unknown.Select(x => x.ToString()), Has.Some.Contains("$.softBodies[0].solver").And.Some.Contains("xpbd or newton"));
        }

        [Test]
        public void A_newton_body_saves_and_restores_bit_identically()
        {
            static (World, SoftBody) Build()
            {
                World w = SoftBodyScenes.WorldWithGround();
                SoftBodyDef def = SoftBodyScenes.Cube(0.4f, 3, new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e6f, 0.4f, 1000f), new Vector3(0, 0.6f, 0));
                def.Solver = SoftSolver.Newton;
                SoftBody b = w.GetSoftBody(w.CreateSoftBody(def));
                return (w, b);
            }
            (World a, _) = Build();
            for (int s = 0; s < 30; s++) a.Step(1 / 60f);
            byte[] state = State.StateRoundTripTests.Save(a);
            for (int s = 0; s < 30; s++) a.Step(1 / 60f);
            (World b, SoftBody body) = Build();
            body.Solver = SoftSolver.Xpbd; // the state carries the solver back
            State.StateRoundTripTests.Restore(b, state);
            Assert.That(body.Solver, Is.EqualTo(SoftSolver.Newton));
            for (int s = 0; s < 30; s++) b.Step(1 / 60f);
            Assert.That(State.StateRoundTripTests.Save(b), Is.EqualTo(State.StateRoundTripTests.Save(a)));
        }

        [Test]
        public void Scene_stiff_bar_newton_sags_as_the_converged_reference()
        {
            SceneInstance scene = RigidScenes.RigidSceneFiles.Build("stiff-bar-newton");
            SoftBodyHandle[] made = SceneSoftBodyBuilder.Build(scene, directory: RigidScenes.RigidSceneFiles.ScenesDirectory);
            SoftBody bar = scene.World.GetSoftBody(made[0]);
            Assert.That(bar.Solver, Is.EqualTo(SoftSolver.Newton));
            float start = bar.GetProbe(0).Y;
            for (int s = 0; s < 120; s++) scene.World.Step(scene.Timestep);
            float sag = start - bar.GetProbe(0).Y;
            float reference = ReferenceTipSag();
            TestContext.Out.WriteLine($"stiff-bar-newton: tip probe sag {sag * 1000:F4} mm, converged {reference * 1000:F4} mm");
            Assert.That(sag, Is.EqualTo(reference).Within(0.1f * reference));
        }
    }
}
