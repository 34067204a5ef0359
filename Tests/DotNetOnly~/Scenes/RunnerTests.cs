using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using Fulcrum.Runner;
using NUnit.Framework;

namespace Fulcrum.Tests.Scenes
{
    public class RunnerTests
    {
        string _dir = "";

        [SetUp]
        public void MakeTempDir()
        {
            _dir = Path.Combine(Path.GetTempPath(), "fulcrum-runner-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void RemoveTempDir() => Directory.Delete(_dir, recursive: true);

        static string ScenesDir()
        {
            for (var d = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); d != null; d = d.Parent)
            {
                string candidate = Path.Combine(d.FullName, "Samples~", "Scenes");
                if (Directory.Exists(candidate)) return candidate;
            }
            throw new AssertionException("Samples~/Scenes not found above the test directory");
        }

        static string Scene(string name) => Path.Combine(ScenesDir(), name + ".json");

        static (int code, string output, string error) Fulcrum(params string[] args)
        {
            var output = new StringWriter();
            var error = new StringWriter();
            int code = Cli.Run(args, output, error);
            return (code, output.ToString(), error.ToString());
        }

        string Write(string name, string text)
        {
            string path = Path.Combine(_dir, name);
            File.WriteAllText(path, text);
            return path;
        }

        static string[] Lines(string text) => text.Split('\n', StringSplitOptions.RemoveEmptyEntries);

        static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);

        [Test]
        public void Check_accepts_every_showcase_scene()
        {
            foreach (string file in Directory.GetFiles(ScenesDir(), "*.json"))
            {
                (int code, string output, string error) = Fulcrum("check", file);
                Assert.That((code, error), Is.EqualTo((0, "")), file);
                Assert.That(output, Does.Contain(": ok ("));
            }
        }

        [Test]
        public void Check_prints_every_error_with_its_path_and_exits_1()
        {
            string path = Write("bad.json", SceneSamples.OneBall(", \"mass\": -1, \"colour\": 3"));
            (int code, string output, string error) = Fulcrum("check", path);
            Assert.That(code, Is.EqualTo(1));
            Assert.That(output, Is.Empty);
            Assert.That(Lines(error), Is.EqualTo(new[]
            {
                $"{path}: $.bodies[0].colour: unknown field (expected one of: name, type, shape, mass, density, material, position, rotation, velocity, angularVelocity, ccd, lockAxes) (line 5, column 114)",
                $"{path}: $.bodies[0].mass: must be > 0, got -1 (line 5, column 100)",
                $"{path}: 2 errors",
            }));
        }

        [Test]
        public void Check_of_malformed_json_names_line_and_column()
        {
            string path = Write("broken.json", "{\n  \"format\": \"fulcrum-scene/1\"\n  \"bodies\": []\n}");
            (int code, _, string error) = Fulcrum("check", path);
            Assert.That(code, Is.EqualTo(1));
            Assert.That(Lines(error)[0], Is.EqualTo($"{path}: $: unexpected '\"', expected ',' or '}}' (line 3, column 3)"));
        }

        [Test]
        public void Usage_errors_exit_2_with_one_line()
        {
            Assert.That(Fulcrum("check").code, Is.EqualTo(2));
            Assert.That(Fulcrum("frobnicate").error, Is.EqualTo("fulcrum: error: unknown command 'frobnicate' (expected run, sweep, check or fuzz; 'fulcrum help' lists them)\n").Or.EqualTo("fulcrum: error: unknown command 'frobnicate' (expected run, sweep, check or fuzz; 'fulcrum help' lists them)" + Environment.NewLine));
            (int code, string output, string error) = Fulcrum("run", Scene("free-fall"), "--steps", "ten");
            Assert.That(code, Is.EqualTo(2));
            Assert.That(output, Is.Empty);
            Assert.That(Lines(error), Is.EqualTo(new[] { "fulcrum: error: --steps: expected an integer >= 1, got 'ten'" }));
            Assert.That(Fulcrum("run", Scene("free-fall"), "--warp", "9").error, Does.StartWith("fulcrum: error: run: unknown flag '--warp' (expected --seconds, --steps,"));
            Assert.That(Fulcrum("run", Scene("free-fall"), "--steps", "2", "--seconds", "1").error, Does.StartWith("fulcrum: error: --steps: give --steps or --seconds, not both"));
            Assert.That(Fulcrum("run", Scene("free-fall"), "--solver", "sor").error, Does.StartWith("fulcrum: error: --solver: expected pgs or tgs, got 'sor'"));
            Assert.That(Fulcrum("run", Scene("free-fall"), "--dt", "-1").error, Does.StartWith("fulcrum: error: --dt: expected a number > 0, got '-1'"));
        }

        [Test]
        public void A_bad_flag_or_scene_writes_nothing()
        {
            string trace = Path.Combine(_dir, "out", "t.csv");
            Assert.That(Fulcrum("run", Scene("free-fall"), "--trace", trace, "--every", "0").code, Is.EqualTo(2));
            string bad = Write("bad.json", SceneSamples.OneBall(shape: "{ \"type\": \"sphere\", \"radius\": -2 }"));
            (int code, string output, string error) = Fulcrum("run", bad, "--trace", trace);
            Assert.That(code, Is.EqualTo(1));
            Assert.That(output, Is.Empty);
            Assert.That(Lines(error), Is.EqualTo(new[] { $"fulcrum: error: {bad}: $.bodies[0].shape.radius: must be > 0, got -2 (line 5, column 62)" }));
            Assert.That(Directory.Exists(Path.Combine(_dir, "out")), Is.False);
        }

        [Test]
        public void A_degenerate_hull_fails_with_its_path_and_writes_nothing()
        {
            string path = Write("hull.json", SceneSamples.OneBall(shape: "{ \"type\": \"convex\", \"points\": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]] }"));
            string trace = Path.Combine(_dir, "hull.csv");
            (int code, _, string error) = Fulcrum("run", path, "--steps", "1", "--trace", trace);
            Assert.That(code, Is.EqualTo(1));
            Assert.That(error, Does.StartWith($"fulcrum: error: {path}: $.bodies[0].shape: "));
            Assert.That(File.Exists(trace), Is.False);
        }

        [Test]
        public void Free_fall_trace_matches_the_semi_implicit_euler_sequence_bit_for_bit()
        {
            string trace = Path.Combine(_dir, "fall.csv");
            (int code, _, string error) = Fulcrum("run", Scene("free-fall"), "--steps", "240", "--trace", trace);
            Assert.That((code, error), Is.EqualTo((0, "")));
            string[] rows = Lines(File.ReadAllText(trace));
            Assert.That(rows[0], Is.EqualTo("step,time,name,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz"));
            Assert.That(rows.Length, Is.EqualTo(1 + 241));
            const float dt = 0.016666668f;
            Vector3 g = new Vector3(0, -9.81f, 0), x = new Vector3(0, 100, 0), v = Vector3.Zero;
            for (int n = 0; n <= 240; n++)
            {
                if (n > 0)
                {
                    v += dt * g;
                    x += v * dt;
                }
                string[] c = rows[1 + n].Split(',');
                Assert.That((c[0], c[2]), Is.EqualTo((n.ToString(CultureInfo.InvariantCulture), "ball")));
                Assert.That(new Vector3(F(c[3]), F(c[4]), F(c[5])), Is.EqualTo(x), $"position at step {n}");
                Assert.That(new Vector3(F(c[10]), F(c[11]), F(c[12])), Is.EqualTo(v), $"velocity at step {n}");
                Assert.That(new Quaternion(F(c[6]), F(c[7]), F(c[8]), F(c[9])), Is.EqualTo(Quaternion.Identity));
            }
            // And the closed form, to within the method's known O(dt) error g t dt / 2.
            float t = 240 * dt;
            Assert.That(x.Y, Is.EqualTo(100 - 9.81f * t * t / 2 - 9.81f * t * dt / 2).Within(2e-4f));
        }

        [Test]
        public void Trace_with_every_k_records_step_0_every_kth_step_and_the_last()
        {
            string trace = Path.Combine(_dir, "sub", "p.csv");
            (int code, string output, _) = Fulcrum("run", Scene("projectile"), "--steps", "25", "--every", "10", "--trace", trace, "--solver", "pgs", "--iterations", "3");
            Assert.That(code, Is.EqualTo(0));
            Assert.That(output, Does.Contain("solver: pgs, 3 iterations, dt 0.016666668 s, 25 steps"));
            string[] rows = Lines(File.ReadAllText(trace));
            Assert.That(rows.Skip(1).Select(r => r.Split(',')[0] + ":" + r.Split(',')[2]), Is.EqualTo(new[]
            {
                "0:shell", "0:spinning-box", "10:shell", "10:spinning-box", "20:shell", "20:spinning-box", "25:shell", "25:spinning-box",
            }));
            string[] world = Lines(File.ReadAllText(Path.Combine(_dir, "sub", "p.world.csv")));
            Assert.That(world[0], Is.EqualTo("step,time,kineticEnergy,potentialEnergy,maxPenetration,maxJointError,contacts,awakeBodies,stepMs"));
            Assert.That(world.Skip(1).Select(r => r.Split(',')[0]), Is.EqualTo(new[] { "0", "10", "20", "25" }));
            string[] last = world[4].Split(',');
            Assert.That(F(last[1]), Is.EqualTo(25 * 0.016666668f).Within(1e-6f), "time");
            Assert.That(int.Parse(last[7], CultureInfo.InvariantCulture), Is.EqualTo(2), "awake bodies");
            Assert.That(File.Exists(Path.Combine(_dir, "sub", "p.soft.csv")), Is.False, "no soft bodies, no soft trace");
            // Energy in the world trace: kinetic at step 0 is 1/2 m v^2 of both bodies plus the box's spin.
            Assert.That(F(world[1].Split(',')[2]), Is.GreaterThan(0.5f * 2 * (12 * 12 + 15 * 15)));
        }

        [Test]
        public void Run_ends_with_the_summary_table()
        {
            (int code, string output, _) = Fulcrum("run", Scene("chain"), "--seconds", "0.5");
            Assert.That(code, Is.EqualTo(0));
            string[] lines = Lines(output.Replace("\r", ""));
            string header = lines[^3], row = lines[^1];
            Assert.That(header.Split("  ", StringSplitOptions.RemoveEmptyEntries).Select(s => s.Trim()), Is.EqualTo(new[]
            {
                "steps", "ms/step median", "ms/step p95", "max penetration (m)", "max joint error (m)", "energy drift (J)", "soft volume error", "min J",
            }));
            string[] cells = row.Split(' ', StringSplitOptions.RemoveEmptyEntries);
            Assert.That(cells[0], Is.EqualTo("30"));
            Assert.That((cells[6], cells[7]), Is.EqualTo(("-", "-")), "no soft bodies");
            // The chain's ball joints hold: the largest anchor gap stays under a centimetre.
            Assert.That(float.Parse(cells[4], CultureInfo.InvariantCulture), Is.InRange(0f, 0.01f), "max joint error (m)");
        }

        [Test]
        public void Soft_sweep_settings_reach_the_xpbd_solver_and_finer_settings_land_nearer_the_reference()
        {
            string outDir = Path.Combine(_dir, "soft-sweep");
            (int code, string output, string error) = Fulcrum("sweep", Scene("jelly"), "--steps", "10", "--solver", "tgs",
                "--iterations", "1,2", "--substeps", "4,60", "--soft-solver", "xpbd", "--out", outDir);
            Assert.That((code, error), Is.EqualTo((0, "")));
            Assert.That(output, Does.Contain("soft bodies Newton 60 substeps x 2 iterations"), "a tet scene's reference is the converged Newton run");
            string[] rows = Lines(File.ReadAllText(Path.Combine(outDir, "sweep.csv")));
            Assert.That(rows[0], Does.EndWith(",softSolver"));
            string[] coarse = rows[1].Split(','), fine = rows[4].Split(',');
            Assert.That((coarse[1], coarse[2], fine[1], fine[2], coarse[10], fine[10]), Is.EqualTo(("1", "4", "2", "60", "xpbd", "xpbd")));
            // The jelly scene's rigid bodies are static, so only the soft settings differ.
            Assert.That(F(coarse[7]), Is.GreaterThan(F(fine[7])), "60 substeps land nearer the converged reference than 4");
            Assert.That(F(coarse[9]), Is.GreaterThan(0f), "volume error applies to soft scenes");
        }

        [Test]
        public void Soft_sweep_compares_both_solvers_and_newton_reaches_the_stiff_bar_reference()
        {
            string outDir = Path.Combine(_dir, "stiff-sweep");
            (int code, _, string error) = Fulcrum("sweep", Scene("stiff-bar"), "--steps", "30", "--solver", "tgs",
                "--iterations", "1,2", "--substeps", "1,10,60", "--out", outDir);
            Assert.That((code, error), Is.EqualTo((0, "")));
            string[] rows = Lines(File.ReadAllText(Path.Combine(outDir, "sweep.csv")));
            Assert.That(rows.Length, Is.EqualTo(1 + 12), "both soft solvers by default on a tet scene");
            string[] Row(string soft, string it, string sub) => rows.Skip(1).Select(r => r.Split(',')).Single(c => c[10] == soft && c[1] == it && c[2] == sub);
            Assert.That(F(Row("newton", "2", "60")[7]), Is.EqualTo(0f), "Newton 2 x 60 is the reference itself");
            float newtonDefault = F(Row("newton", "1", "1")[7]), xpbdDefault = F(Row("xpbd", "1", "10")[7]);
            TestContext.Out.WriteLine($"stiff-bar sweep: reference error Newton 1x1 {newtonDefault:E2} m, XPBD 1x10 {xpbdDefault:E2} m");
            Assert.That(newtonDefault, Is.LessThan(0.01f * xpbdDefault), "on the stiff bar Newton at its default is 100x nearer than XPBD at its default");
            Assert.That(File.ReadAllText(Path.Combine(outDir, "sweep.svg")), Does.Contain("soft Newton").And.Contain("soft XPBD"));
            (code, _, error) = Fulcrum("sweep", Scene("stiff-bar"), "--soft-solver", "fem", "--out", outDir);
            Assert.That((code, error.Trim()), Is.EqualTo((Cli.ExitUsage, "fulcrum: error: --soft-solver: unknown solver 'fem' (expected xpbd or newton)")));
        }

        [Test]
        public void Sweep_writes_csv_and_svg_and_the_reference_setting_has_zero_error()
        {
            string outDir = Path.Combine(_dir, "sweep");
            (int code, string output, string error) = Fulcrum("sweep", Scene("projectile"), "--steps", "20",
                "--iterations", "2,16", "--substeps", "1,8", "--out", outDir);
            Assert.That((code, error), Is.EqualTo((0, "")));
            string[] rows = Lines(File.ReadAllText(Path.Combine(outDir, "sweep.csv")));
            Assert.That(rows[0], Is.EqualTo("solver,iterations,substeps,dt,msPerStep,maxPenetration,maxJointError,referenceError,energyDrift,volumeError,softSolver"));
            Assert.That(rows.Skip(1).Select(r => string.Join(",", r.Split(',').Take(4))), Is.EqualTo(new[]
            {
                "pgs,2,1,0.016666668", "pgs,16,1,0.016666668",
                "tgs,2,1,0.016666668", "tgs,2,8,0.016666668", "tgs,16,1,0.016666668", "tgs,16,8,0.016666668",
            }));
            foreach (string r in rows.Skip(1))
            {
                string[] c = r.Split(',');
                Assert.That(c[6], Is.Empty, "maxJointError does not apply");
                Assert.That(c[9], Is.Empty, "volumeError does not apply");
                Assert.That(F(c[7]), Is.GreaterThanOrEqualTo(0f));
                Assert.That(F(c[4]), Is.GreaterThan(0f));
            }
            Assert.That(F(rows[6].Split(',')[7]), Is.EqualTo(0f), "tgs 16x8 is the reference itself");
            string svg = File.ReadAllText(Path.Combine(outDir, "sweep.svg"));
            Assert.That(svg, Does.StartWith("<svg xmlns=\"http://www.w3.org/2000/svg\"").And.Contain("Pareto front").And.Contain("TGS").And.Contain("PGS"));
            Assert.That(output, Does.Contain("wrote "));
        }

        [Test]
        public void The_report_runs_every_showcase_scene()
        {
            (int code, string output, string error) = Fulcrum("report", ScenesDir(), "--seconds", "0.25");
            Assert.That((code, error), Is.EqualTo((0, "")));
            foreach (string file in Directory.GetFiles(ScenesDir(), "*.json"))
                Assert.That(output, Does.Contain("\n" + Path.GetFileNameWithoutExtension(file) + " "), file);
            Assert.That(output, Does.Not.Contain("not run"));
        }
    }
}
