using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Numerics;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// Milliseconds per step of the constraint solver's scenes: a large box pyramid and a box
    /// pile under TGS and PGS, warm starting on and off, one thread against all, and the bytes a
    /// warm step allocates (must be 0), and the SIMD contact path against the scalar one.
    /// Sleeping is off so every step does the full work.
    /// Medians over the measured steps (p95 beside them); the pile is measured after it settled.
    /// </summary>
    public sealed class SolverBenchmark : IBenchmark
    {
        public string Name => "solver";

        public string Description => "ms/step: pyramid and pile, PGS vs TGS, warm start on/off, 1 thread vs all, bytes/step";

        public void Run(TextWriter output, bool quick)
        {
            int pyramidBase = quick ? 12 : 30;
            int pile = quick ? 4 : 8;
            int warm = quick ? 30 : 120, measured = quick ? 30 : 120;
            int all = Environment.ProcessorCount;
            output.WriteLine($"pyramid: {pyramidBase} at the base ({pyramidBase * (pyramidBase + 1) / 2} boxes); pile: {pile}x{pile}x{pile} boxes dropped; {warm} steps to settle, {measured} measured, dt 1/60 s");
            output.WriteLine();
            output.WriteLine("| scene | solver | settings | threads | manifolds | ms/step median | p95 | solve ms median | bytes/step |");
            output.WriteLine("|---|---|---|---|---|---|---|---|---|");
            Row(output, "pyramid", SolverType.Tgs, "default (4x4, block)", 1, w => Pyramid(w, pyramidBase), s => { }, warm, measured);
            Row(output, "pyramid", SolverType.Tgs, "default (4x4, block)", all, w => Pyramid(w, pyramidBase), s => { }, warm, measured);
            Row(output, "pyramid", SolverType.Tgs, "SIMD path off", 1, w => Pyramid(w, pyramidBase), s => s.Scalar = true, warm, measured);
            Row(output, "pyramid", SolverType.Tgs, "warm start off", 1, w => Pyramid(w, pyramidBase), s => s.WarmStarting = false, warm, measured);
            Row(output, "pyramid", SolverType.Tgs, "block off", 1, w => Pyramid(w, pyramidBase), s => s.BlockSolver = false, warm, measured);
            Row(output, "pyramid", SolverType.Tgs, "manifold reuse off", 1, w => Pyramid(w, pyramidBase), s => s.ManifoldReuse = false, warm, measured);
            Row(output, "pyramid", SolverType.Pgs, "default (4 it, 2 pos)", 1, w => Pyramid(w, pyramidBase), s => { }, warm, measured);
            Row(output, "pyramid", SolverType.Pgs, "warm start off", 1, w => Pyramid(w, pyramidBase), s => s.WarmStarting = false, warm, measured);
            Row(output, "pile", SolverType.Tgs, "default (4x4, block)", 1, w => Pile(w, pile), s => { }, warm, measured);
            Row(output, "pile", SolverType.Tgs, "default (4x4, block)", all, w => Pile(w, pile), s => { }, warm, measured);
            Row(output, "pile", SolverType.Tgs, "SIMD path off", 1, w => Pile(w, pile), s => s.Scalar = true, warm, measured);
            Row(output, "pile", SolverType.Tgs, "manifold reuse off", 1, w => Pile(w, pile), s => s.ManifoldReuse = false, warm, measured);
            Row(output, "pile", SolverType.Pgs, "default (4 it, 2 pos)", 1, w => Pile(w, pile), s => { }, warm, measured);
            Row(output, "tower 40", SolverType.Tgs, "default (4x4, block)", 1, w => Tower(w, 40), s => { }, warm, measured);
            Row(output, "tower 40", SolverType.Pgs, "default (4 it, 2 pos)", 1, w => Tower(w, 40), s => { }, warm, measured);
        }

        static void Row(TextWriter output, string scene, SolverType solver, string label, int threads,
            Action<World> build, Action<RefBox> edit, int warm, int measured)
        {
            var box = new RefBox { Settings = WorldSettings.Default };
            box.Settings.Solver = solver;
            box.Settings.EnableSleeping = false;
            box.Settings.Threads = threads;
            edit(box);
            var w = new World(box.Settings);
            w.SolverContextForTests.WideContacts = !box.Scalar;
            Ground(w);
            build(w);
            for (int n = 0; n < warm; n++) w.Step(1f / 60f);
            var total = new double[measured];
            var solve = new double[measured];
            long bytes = 0;
            for (int n = 0; n < measured; n++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                w.Step(1f / 60f);
                bytes += GC.GetAllocatedBytesForCurrentThread() - before;
                total[n] = w.LastStepProfile.Total;
                solve[n] = w.LastStepProfile.Solve;
            }
            Array.Sort(total);
            Array.Sort(solve);
            output.WriteLine($"| {scene} | {solver} | {label} | {threads} | {w.Contacts.ManifoldCount} | {total[measured / 2]:F3} | {total[measured * 95 / 100]:F3} | {solve[measured / 2]:F3} | {bytes / measured} |");
        }

        sealed class RefBox
        {
            public WorldSettings Settings;
            public bool WarmStarting { set => Settings.WarmStarting = value; }
            public bool BlockSolver { set => Settings.BlockSolver = value; }
            public bool ManifoldReuse { set => Settings.ManifoldReuseDistance = value ? WorldSettings.Default.ManifoldReuseDistance : 0; }
            public bool Scalar;
        }

        static void Ground(World w)
        {
            BodyHandle g = w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            w.AddShape(g, ShapeDef.Of(ShapeGeometry.Box(new Vector3(100, 0.5f, 100))));
        }

        static void Cube(World w, Vector3 at)
        {
            BodyDef d = BodyDef.Dynamic(at);
            d.Mass = 1f;
            w.AddShape(w.CreateBody(d), ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
        }

        static void Pyramid(World w, int baseCount)
        {
            for (int row = 0; row < baseCount; row++)
                for (int i = 0; i < baseCount - row; i++)
                    Cube(w, new Vector3(-0.5f * (baseCount - row - 1) + i, 0.5f + row, 0));
        }

        static void Tower(World w, int count)
        {
            for (int i = 0; i < count; i++) Cube(w, new Vector3(0, 0.5f + i, 0));
        }

        // Boxes in a loose grid, a little turned, dropped into a heap.
        static void Pile(World w, int n)
        {
            for (int x = 0; x < n; x++)
                for (int y = 0; y < n; y++)
                    for (int z = 0; z < n; z++)
                    {
                        BodyDef d = BodyDef.Dynamic(new Vector3(1.2f * x - 0.6f * n, 1f + 1.2f * y, 1.2f * z - 0.6f * n));
                        d.Mass = 1f;
                        d.Rotation = Quaternion.CreateFromYawPitchRoll(0.3f * x, 0.2f * y, 0.1f * z);
                        w.AddShape(w.CreateBody(d), ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
                    }
        }
    }
}
