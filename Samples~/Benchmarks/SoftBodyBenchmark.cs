using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Numerics;
using Fulcrum.SoftBodies;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// Milliseconds per 60 Hz step of the soft-body stage (default substeps, stable Neo-Hookean
    /// rubber falling onto a ground plane) for tet meshes of ~1k, ~10k and ~50k elements and a
    /// 64 x 64 cloth over a sphere, on 1 thread and on every core; and the bytes allocated per
    /// step (must be 0). The 1-thread and N-thread worlds of a scene are stepped in alternation
    /// (a few steps each, in turn) so that a change in the machine's load hits both alike; each
    /// row gives the mean, median and p95 of its steps. The last lines check issue 16's bars:
    /// the 10k-tet box at most 5 ms per step on 1 thread, the 50k-tet box at most 16 ms with 2
    /// threads, and N threads never slower than 1 above 5k elements. `--threads=1,2,4,8,16` steps
    /// each scene on every count given instead of 1 and all cores.
    /// </summary>
    public sealed class SoftBodyBenchmark : IBenchmark
    {
        public string Name => "softbody";

        public string Description => "ms/step and bytes/step of XPBD soft bodies: 1k/10k/50k tets, 64x64 cloth; 1 vs N threads alternated";

        public void Run(TextWriter output, bool quick)
        {
            int warm = quick ? 5 : 30, measured = quick ? 10 : 60;
            const int turn = 5; // steps per world per turn
            int cores = Environment.ProcessorCount;
            int[]? counts = ThreadCounts(output, out bool bad);
            if (bad) return;
            output.WriteLine($"{"scene",-28} {"elements",9} {"threads",7} {"substeps",8} {"mean ms",8} {"median ms",10} {"p95 ms",8} {"bytes/step",10}");
            var scenes = new List<(string, Func<int, World>)>
            {
                ("box 6x6x5 (1k tets)", t => Jelly(t, 6, 6, 5)),
                ("box 12x12x12 (10k tets)", t => Jelly(t, 12, 12, 12)),
                ("cloth 64x64 over a ball", Cloth),
            };
            if (!quick) scenes.Add(("box 20x20x21 (50k tets)", t => Jelly(t, 20, 20, 21)));
            var bars = new List<string>();
            foreach (var (name, build) in scenes)
            {
                int[] threadCounts = counts ?? (cores > 1 ? new[] { 1, cores } : new[] { 1 });
                var worlds = new World[threadCounts.Length];
                var times = new double[threadCounts.Length][];
                var bytes = new long[threadCounts.Length];
                const float dt = 1f / 60f;
                for (int k = 0; k < worlds.Length; k++)
                {
                    worlds[k] = build(threadCounts[k]);
                    for (int i = 0; i < warm; i++) worlds[k].Step(dt);
                    times[k] = new double[measured];
                }
                for (int done = 0; done < measured; done += turn)
                {
                    for (int k = 0; k < worlds.Length; k++)
                    {
                        long before = GC.GetAllocatedBytesForCurrentThread();
                        for (int i = done; i < Math.Min(measured, done + turn); i++)
                        {
                            long t0 = Stopwatch.GetTimestamp();
                            worlds[k].Step(dt);
                            times[k][i] = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
                        }
                        bytes[k] += GC.GetAllocatedBytesForCurrentThread() - before;
                    }
                }
                var medians = new double[worlds.Length];
                for (int k = 0; k < worlds.Length; k++)
                {
                    SoftBody body = SoftBodySystem.Of(worlds[k])![0];
                    double mean = 0;
                    foreach (double t in times[k]) mean += t;
                    mean /= measured;
                    Array.Sort(times[k]);
                    medians[k] = times[k][measured / 2];
                    output.WriteLine($"{name,-28} {body.ElementCount,9} {threadCounts[k],7} {body.SubstepsFor(dt),8} {mean,8:F3} {medians[k],10:F3} {times[k][(int)(measured * 0.95)],8:F3} {bytes[k] / measured,10}");
                    worlds[k].StopThreads();
                }
                if (name.Contains("10k")) bars.Add($"bar: 10k tets, 1 thread: median {medians[0]:F2} ms/step (<= 5): {(medians[0] <= 5 ? "met" : "not met")}");
                if (name.Contains("50k") && worlds.Length > 1)
                    bars.Add($"bar: 50k tets, {threadCounts[1]} threads: median {medians[1]:F2} ms/step (<= 16): {(medians[1] <= 16 ? "met" : "not met")}");
                int elements = SoftBodySystem.Of(worlds[0])![0].ElementCount;
                if (elements > 5000 && worlds.Length > 1)
                    bars.Add($"bar: {name}, {threadCounts[1]} threads / 1 thread: {medians[1] / medians[0]:F2} (<= 1): {(medians[1] <= medians[0] ? "met" : "not met")}");
            }
            foreach (string bar in bars) output.WriteLine(bar);
            Kernels(output, quick);
        }

        /// <summary>
        /// "--threads=1,2,4,8,16": the thread counts to step each scene with, stepped in alternation
        /// (1 is always first, the reference of the bars); null without the option.
        /// </summary>
        static int[]? ThreadCounts(TextWriter output, out bool bad)
        {
            bad = false;
            string? text = null;
            foreach (string arg in Environment.GetCommandLineArgs())
                if (arg.StartsWith("--threads=", StringComparison.Ordinal)) text = arg.Substring("--threads=".Length);
            if (text == null) return null;
            var counts = new List<int> { 1 };
            foreach (string part in text.Split(','))
            {
                if (!int.TryParse(part, System.Globalization.NumberStyles.Integer, System.Globalization.CultureInfo.InvariantCulture, out int t) || t < 1 || t > 256)
                {
                    output.WriteLine($"--threads needs thread counts from 1 to 256 separated by commas, got '{text}'; nothing was run.");
                    bad = true;
                    return null;
                }
                if (!counts.Contains(t)) counts.Add(t);
            }
            counts.Sort();
            return counts.ToArray();
        }

        /// <summary>
        /// The tet passes alone, eight-lane against scalar kernels in one process on the same
        /// state: the least time over repeated passes (the figure least moved by other load on
        /// the machine), in ns per tet, for the 10k-tet box after it has fallen for half a second.
        /// </summary>
        static void Kernels(TextWriter output, bool quick)
        {
            World world = Jelly(1, 12, 12, 12);
            SoftBody b = SoftBodySystem.Of(world)![0];
            for (int i = 0; i < 30; i++) world.Step(1f / 60f);
            var x = (Vector3[])b.X.Clone();
            var v = (Vector3[])b.V.Clone();
            float h = 1f / 600f;
            StableNeoHookeanEnergy model = b.StableModel;
            bool was = TetStream.WideKernels;
            int reps = quick ? 5 : 40;
            var best = new double[2, 2];
            for (int round = 0; round < 4; round++)
            {
                foreach (bool wide in new[] { false, true })
                {
                    if (wide && !was) continue;
                    TetStream.WideKernels = wide;
                    int k = wide ? 1 : 0;
                    for (int rep = 0; rep < reps; rep++)
                    {
                        Array.Copy(x, b.X, x.Length);
                        Array.Copy(v, b.V, v.Length);
                        long t0 = Stopwatch.GetTimestamp();
                        for (int c = 0; c + 1 < b.TetColors.Length; c++) Project(b, model, b.TetColors[c], b.TetColors[c + 1], h);
                        long t1 = Stopwatch.GetTimestamp();
                        for (int c = 0; c + 1 < b.TetColors.Length; c++) Damp(b, model, b.TetColors[c], b.TetColors[c + 1], h);
                        long t2 = Stopwatch.GetTimestamp();
                        double p = (t1 - t0) * 1e9 / Stopwatch.Frequency / b.Tets.Length, d = (t2 - t1) * 1e9 / Stopwatch.Frequency / b.Tets.Length;
                        if (best[k, 0] == 0 || p < best[k, 0]) best[k, 0] = p;
                        if (best[k, 1] == 0 || d < best[k, 1]) best[k, 1] = d;
                    }
                }
            }
            TetStream.WideKernels = was;
            output.WriteLine($"tet passes of the 10k box, least ns per tet over {4 * reps} passes: projection / damping / both x 10 substeps");
            output.WriteLine($"  scalar kernels    {best[0, 0],6:F1} / {best[0, 1],6:F1} ns  = {(best[0, 0] + best[0, 1]) * 10 * b.Tets.Length / 1e6:F2} ms/step");
            if (was) output.WriteLine($"  8-lane kernels    {best[1, 0],6:F1} / {best[1, 1],6:F1} ns  = {(best[1, 0] + best[1, 1]) * 10 * b.Tets.Length / 1e6:F2} ms/step ({(best[0, 0] + best[0, 1]) / (best[1, 0] + best[1, 1]):F2}x)");
        }

        static void Project(SoftBody b, in StableNeoHookeanEnergy model, int start, int end, float h)
        {
#if NET
            if (TetStream.WideKernels) start = XpbdTetSolverWide.Solve(model, b.TetData, b.TetLambda, true, b.X, b.XPrev, start, end, h);
#endif
            XpbdTetSolver.Solve(model, b.TetData, b.TetLambda, true, b.X, b.XPrev, b.W, b.M, b.FreeW, start, end, h);
        }

        static void Damp(SoftBody b, in StableNeoHookeanEnergy model, int start, int end, float h)
        {
#if NET
            if (TetStream.WideKernels) start = RayleighDampingWide.Tets(model.DeviatoricStiffness, model.HydrostaticStiffness, b.TetData, b.X, b.V, start, end, h, b.DampingTime);
#endif
            RayleighDamping.Tets(model.DeviatoricStiffness, model.HydrostaticStiffness, b.TetData, b.X, b.V, b.W, b.M, b.FreeW, start, end, h, b.DampingTime);
        }

        static World Ground(int threads)
        {
            WorldSettings settings = WorldSettings.Default;
            settings.Threads = threads;
            var world = new World(settings);
            BodyHandle ground = world.CreateBody(BodyDef.Static(Vector3.Zero));
            world.AddShape(ground, ShapeDef.Of(ShapeGeometry.Plane(Vector3.UnitY, 0)));
            return world;
        }

        static World Jelly(int threads, int nx, int ny, int nz)
        {
            World world = Ground(threads);
            SoftMesh mesh = SoftMesh.Box(new Vector3(0.1f * nx, 0.1f * ny, 0.1f * nz), nx, ny, nz);
            world.CreateSoftBody(SoftBodyDef.Of(mesh, MaterialPresets.Rubber, new Vector3(0, 0.05f * ny + 0.1f, 0)));
            return world;
        }

        static World Cloth(int threads)
        {
            World world = Ground(threads);
            BodyHandle ball = world.CreateBody(BodyDef.Static(new Vector3(0, 0.5f, 0)));
            world.AddShape(ball, ShapeDef.Of(ShapeGeometry.Sphere(0.4f)));
            world.CreateSoftBody(SoftBodyDef.Of(SoftMesh.Cloth(2f, 2f, 64, 64), MaterialPresets.Cloth, new Vector3(0, 1f, 0)));
            return world;
        }
    }
}
