using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Numerics;
using Fulcrum.SoftBodies;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// The two soft solvers side by side on the cases that separate them: error against a true
    /// answer (the converged static state of the same mesh, a closed form, or volume) and
    /// ms/step, at the default settings.
    /// </summary>
    public sealed class SoftSolverBenchmark : IBenchmark
    {
        public string Name => "soft-solvers";

        public string Description => "XPBD vs Newton soft solver: stiff cantilever sag vs converged, jelly volume, heavy plate strain vs closed form; error and ms/step";

        public void Run(TextWriter output, bool quick)
        {
            int runs = quick ? 1 : 3;
            output.WriteLine($"Defaults (60 Hz; XPBD 10 substeps x 1 iteration; Newton 1 substep x 1 iteration when touching nothing, 10 otherwise).");
            output.WriteLine($"ms/step: mean and median over the measured steps of each run, [min-max of the run medians] over {runs} runs; the machine may be shared.");
            output.WriteLine();
            output.WriteLine("| case | truth | solver | result | error | ms/step mean / median [range] |");
            output.WriteLine("|---|---|---|---|---|---|");
            foreach (SoftSolver solver in new[] { SoftSolver.Xpbd, SoftSolver.Newton }) Cantilever(output, solver, runs);
            foreach (SoftSolver solver in new[] { SoftSolver.Xpbd, SoftSolver.Newton }) Jelly(output, solver, runs);
            foreach (SoftSolver solver in new[] { SoftSolver.Xpbd, SoftSolver.Newton }) Plate(output, solver, runs);
        }

        static NeoHookeanMaterial Stiff => new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e9f, 0.3f, 1000f);

        static void Cantilever(TextWriter output, SoftSolver solver, int runs)
        {
            SoftMesh mesh = SoftMesh.Box(new Vector3(1, 0.1f, 0.1f), 10, 1, 1);
            var eq = new StaticEquilibrium(mesh, Stiff);
            eq.AddGravity(new Vector3(0, -9.81f, 0));
            Vector3[] rest = mesh.Vertices.ToArray();
            for (int i = 0; i < rest.Length; i++) if (rest[i].X < -0.499f) eq.Pin(i);
            eq.Solve(100);
            float reference = TipSag(rest, i => eq.Position(i));
            float sag = 0;
            var medians = new List<double>();
            var all = new List<double>();
            for (int run = 0; run < runs; run++)
            {
                var w = new World(WorldSettings.Default);
                SoftBodyDef def = SoftBodyDef.Of(mesh, Stiff, Vector3.Zero);
                def.Pins = new[] { SoftPin.ToWorld(new Vector3(-0.5f, -1, -1), new Vector3(-0.5f, 1, 1)) };
                def.Solver = solver;
                SoftBody bar = w.GetSoftBody(w.CreateSoftBody(def));
                medians.Add(Time(w, 180, all));
                sag = TipSag(rest, i => bar.Positions[i]);
            }
            output.WriteLine($"| cantilever 1 m, E 1e9, 44 vertices, 3 s | converged sag {reference * 1000:F3} mm | {solver} | {sag * 1000:F3} mm | {100 * (sag / reference - 1):F1} % | {Stats(all, medians)} |");
        }

        static void Jelly(TextWriter output, SoftSolver solver, int runs)
        {
            float lowest = 1, end = 1;
            var medians = new List<double>();
            var all = new List<double>();
            for (int run = 0; run < runs; run++)
            {
                var w = new World(WorldSettings.Default);
                w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0))), ShapeDef.Of(ShapeGeometry.Box(new Vector3(5, 0.5f, 5))));
                SoftBodyDef def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.5f), 4, 4, 4), new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e4f, 0.4999f, 1030f), new Vector3(0, 1, 0));
                def.Solver = solver;
                SoftBody jelly = w.GetSoftBody(w.CreateSoftBody(def));
                lowest = 1;
                var ms = new List<double>();
                for (int s = 0; s < 240; s++)
                {
                    long t = Stopwatch.GetTimestamp();
                    w.Step(1 / 60f);
                    ms.Add((Stopwatch.GetTimestamp() - t) * 1000.0 / Stopwatch.Frequency);
                    lowest = MathF.Min(lowest, jelly.ComputeStats().VolumeRatio);
                }
                all.AddRange(ms);
                medians.Add(Median(ms));
                end = jelly.ComputeStats().VolumeRatio;
            }
            output.WriteLine($"| jelly 0.5 m, nu 0.4999, dropped 0.75 m, 125 vertices, 4 s | volume 1 | {solver} | lowest {lowest:F4}, at rest {end:F4} | {100 * (1 - lowest):F2} % at impact | {Stats(all, medians)} |");
        }

        static void Plate(TextWriter output, SoftSolver solver, int runs)
        {
            float strain = 0;
            var medians = new List<double>();
            var all = new List<double>();
            var material = new NeoHookeanMaterial(MaterialModel.StableNeoHookean, 1e7f, 0.3f, 1000f);
            for (int run = 0; run < runs; run++)
            {
                var w = new World(WorldSettings.Default);
                w.AddShape(w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0))), ShapeDef.Of(ShapeGeometry.Box(new Vector3(3, 0.5f, 3))));
                SoftBodyDef def = SoftBodyDef.Of(SoftMesh.Box(new Vector3(0.2f), 4, 4, 4), material, new Vector3(0, 0.105f, 0));
                def.Probes = new[] { new Vector3(0, 0.1f, 0), new Vector3(0, -0.1f, 0) };
                def.Solver = solver;
                SoftBody cube = w.GetSoftBody(w.CreateSoftBody(def));
                BodyDef plate = BodyDef.Dynamic(new Vector3(0, 0.235f, 0));
                plate.Mass = 2000;
                w.AddShape(w.CreateBody(plate), ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.3f, 0.02f, 0.3f))));
                medians.Add(Time(w, 300, all));
                strain = 1 - (cube.GetProbe(0) - cube.GetProbe(1)).Length() / 0.2f;
            }
            output.WriteLine($"| 2000 kg plate on an 8 kg cube, E 1e7 (plate-on-soft-cube), 5 s | uniaxial closed form 4.77 % | {solver} | strain {100 * strain:F2} % | {100 * (strain / 0.0477f - 1):F1} % | {Stats(all, medians)} |");
        }

        static float TipSag(Vector3[] rest, Func<int, Vector3> at)
        {
            float sag = 0;
            int n = 0;
            for (int i = 0; i < rest.Length; i++)
                if (rest[i].X > 0.499f) { sag += rest[i].Y - at(i).Y; n++; }
            return sag / n;
        }

        static double Time(World w, int steps, List<double> all)
        {
            var ms = new List<double>();
            for (int s = 0; s < steps; s++)
            {
                long t = Stopwatch.GetTimestamp();
                w.Step(1 / 60f);
                ms.Add((Stopwatch.GetTimestamp() - t) * 1000.0 / Stopwatch.Frequency);
            }
            all.AddRange(ms);
            return Median(ms);
        }

        static double Median(List<double> v)
        {
            var s = v.OrderBy(x => x).ToList();
            return s.Count % 2 == 1 ? s[s.Count / 2] : 0.5 * (s[s.Count / 2 - 1] + s[s.Count / 2]);
        }

        static string Stats(List<double> all, List<double> medians) =>
            $"{all.Average():F3} / {Median(all):F3} [{medians.Min():F3}-{medians.Max():F3}]";
    }
}
