using System;
using System.Diagnostics;
using System.IO;
using System.Numerics;

namespace Fulcrum.Benchmarks
{
    /// <summary>
    /// Issue 4's large scenes: a 2D-style pyramid of 100 at the base (5,050 boxes in one plane),
    /// 40 pyramids of 20 side by side (8,400 boxes), a 4k-box pile and 100 capsule ragdolls,
    /// priced in ms/step under TGS on one thread and on all cores, PGS, and TGS without warm
    /// starting, with the bytes a step allocates; then how a pile's cost grows with its size.
    /// Each scene is built once and settled; the settings are then switched on the live world
    /// (each switch gets a short untimed re-warm) so every setting prices the same settled state.
    /// Sleeping is off so the timing prices the solve, not sleep.
    /// </summary>
    public sealed class SolverScalingBenchmark : IBenchmark
    {
        const float Dt = 1f / 60f;

        public string Name => "scaling";

        public string Description => "ms/step of 5k-8k box scenes, pile and ragdolls: TGS 1/all threads, PGS, warm start off, manifold reuse off, bytes/step, growth with body count";

        public void Run(TextWriter output, bool quick)
        {
            var clock = Stopwatch.StartNew();
            int pyramidBase = quick ? 20 : 100;
            int pyramids = quick ? 4 : 40;
            int pile = quick ? 500 : 4000;
            int ragdolls = quick ? 10 : 100;
            int[] growth = quick ? new[] { 250, 500 } : new[] { 500, 1000, 2000, 4000 };
            int settle = quick ? 40 : 60, pileSettle = quick ? 90 : 120, rewarm = 8;
            int measured = quick ? 20 : 40;
            int all = Environment.ProcessorCount;

            output.WriteLine($"settle {settle} steps ({pileSettle} for piles and ragdolls), {rewarm} untimed steps after each settings switch, {measured} timed steps, dt 1/60 s, sleeping off; bytes/step = GC.GetAllocatedBytesForCurrentThread over the timed window (all threads in brackets)");
            output.WriteLine();
            output.WriteLine("mean: mean wall ms per step; cpu: the process's CPU ms per step (every thread; NaN where the OS does not give it); stages: mean wall ms per step of broad phase / narrow phase / islands / solve / sleep and events (World.LastStepProfile)");
            output.WriteLine();
            output.WriteLine("| scene | bodies | joints | setting | threads | manifolds | ms/step median | p95 | ms per 1k bodies | bytes/step | mean | cpu | stages b / n / i / s / e |");
            output.WriteLine("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
            Scene(output, $"pyramid {pyramidBase}", w => Pyramid(w, pyramidBase, 0f), settle, rewarm, measured, all);
            Scene(output, $"{pyramids} pyramids of 20", w => { for (int p = 0; p < pyramids; p++) Pyramid(w, 20, 2f * (p - 0.5f * (pyramids - 1))); }, settle, rewarm, measured, all);
            Scene(output, $"pile {pile}", w => Pile(w, pile), pileSettle, rewarm, measured, all);
            Scene(output, $"{ragdolls} ragdolls", w => Ragdolls(w, ragdolls), pileSettle, rewarm, measured, all);

            output.WriteLine();
            output.WriteLine("growth: box piles, TGS, 1 thread");
            output.WriteLine();
            output.WriteLine("| boxes | manifolds | ms/step median | p95 | ms per 1k bodies | bytes/step |");
            output.WriteLine("|---|---|---|---|---|---|");
            foreach (int n in growth)
            {
                World w = Build(w2 => Pile(w2, n));
                for (int s = 0; s < pileSettle; s++) w.Step(Dt);
                Measurement m = Measure(w, measured);
                output.WriteLine($"| {n} | {w.Contacts.ManifoldCount} | {m.Median:F2} | {m.P95:F2} | {1000.0 * m.Median / n:F2} | {m.Bytes} ({m.AllBytes}) |");
            }
            output.WriteLine();
            output.WriteLine($"run time {clock.Elapsed.TotalSeconds:F0} s");
        }

        // Settles once under TGS on one thread, then prices each setting on the same live world.
        static void Scene(TextWriter output, string name, Action<World> build, int settle, int rewarm, int measured, int all)
        {
            World w = Build(build);
            for (int s = 0; s < settle; s++) w.Step(Dt);
            int bodies = w.BodyCount - 1;
            int joints = w.JointCount;
            Row(output, w, name, bodies, joints, "TGS", SolverType.Tgs, true, 1, rewarm, measured);
            Row(output, w, name, bodies, joints, "TGS", SolverType.Tgs, true, all, rewarm, measured);
            Row(output, w, name, bodies, joints, "PGS", SolverType.Pgs, true, 1, rewarm, measured);
            // Reuse off before warm start off: without warm starting part of a pyramid collapses,
            // and every row prices the same live world.
            Row(output, w, name, bodies, joints, "TGS manifold reuse off", SolverType.Tgs, true, 1, rewarm, measured, reuse: false);
            Row(output, w, name, bodies, joints, "TGS warm start off", SolverType.Tgs, false, 1, rewarm, measured);
        }

        static void Row(TextWriter output, World w, string name, int bodies, int joints, string label,
            SolverType solver, bool warmStarting, int threads, int rewarm, int measured, bool reuse = true)
        {
            WorldSettings s = w.Settings;
            s.Solver = solver;
            s.WarmStarting = warmStarting;
            s.ManifoldReuseDistance = reuse ? WorldSettings.Default.ManifoldReuseDistance : 0;
            s.Threads = threads;
            w.Settings = s;
            for (int n = 0; n < rewarm; n++) w.Step(Dt);
            Measurement m = Measure(w, measured);
            output.WriteLine($"| {name} | {bodies} | {joints} | {label} | {threads} | {w.Contacts.ManifoldCount} | {m.Median:F2} | {m.P95:F2} | {1000.0 * m.Median / bodies:F2} | {m.Bytes} ({m.AllBytes}) | {m.Mean:F2} | {m.Cpu:F2} | {m.Stages} |");
        }

        struct Measurement
        {
            public double Median, P95, Mean, Cpu;
            public long Bytes, AllBytes;
            public string Stages;
        }

        static Measurement Measure(World w, int measured)
        {
            var ms = new double[measured];
            var stages = new double[StepProfile.StageCount];
            double sum = 0;
            long before = GC.GetAllocatedBytesForCurrentThread();
            long allBefore = GC.GetTotalAllocatedBytes(true);
            double cpuBefore = Peers.ThreadClock.ProcessNowMs();
            for (int n = 0; n < measured; n++)
            {
                long t0 = Stopwatch.GetTimestamp();
                w.Step(Dt);
                ms[n] = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
                sum += ms[n];
                StepProfile profile = w.LastStepProfile;
                for (int stage = 0; stage < stages.Length; stage++) stages[stage] += profile[(StepStage)stage];
            }
            double cpu = (Peers.ThreadClock.ProcessNowMs() - cpuBefore) / measured;
            long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
            long allBytes = GC.GetTotalAllocatedBytes(true) - allBefore;
            Array.Sort(ms);
            return new Measurement
            {
                Mean = sum / measured,
                Cpu = cpu,
                Stages = $"{stages[0] / measured:F2} / {stages[1] / measured:F2} / {stages[2] / measured:F2} / {stages[3] / measured:F2} / {stages[6] / measured:F2}",
                Median = ms[measured / 2],
                P95 = ms[Math.Min(measured - 1, measured * 95 / 100)],
                Bytes = bytes / measured,
                AllBytes = allBytes / measured,
            };
        }

        static World Build(Action<World> build)
        {
            WorldSettings s = WorldSettings.Default;
            s.EnableSleeping = false;
            var w = new World(s);
            BodyHandle g = w.CreateBody(BodyDef.Static(new Vector3(0, -0.5f, 0)));
            w.AddShape(g, ShapeDef.Of(ShapeGeometry.Box(new Vector3(200, 0.5f, 200))));
            build(w);
            // Capacity up front (World.Reserve), so the bytes column shows what a step itself
            // allocates, not the buffers doubling while a pile first collapses.
            w.Reserve(w.BodyCount, 16 * w.BodyCount);
            return w;
        }

        static void Box(World w, Vector3 at, Quaternion rotation)
        {
            BodyDef d = BodyDef.Dynamic(at);
            d.Rotation = rotation;
            d.Mass = 1f;
            w.AddShape(w.CreateBody(d), ShapeDef.Of(ShapeGeometry.Box(new Vector3(0.5f))));
        }

        // Box2D's large pyramid in the plane z = const: rows of base, base-1, ..., 1 unit boxes.
        static void Pyramid(World w, int baseCount, float z)
        {
            for (int row = 0; row < baseCount; row++)
                for (int i = 0; i < baseCount - row; i++)
                    Box(w, new Vector3(-0.5f * (baseCount - row - 1) + i, 0.5f + row, z), Quaternion.Identity);
        }

        // Six loose layers over a square footprint, odd layers shifted half a pitch so no box
        // lands square on the one below, each box turned at random (a 1.8 m pitch clears a unit
        // cube's 1.73 m diagonal), dropped into a heap; the same height for every count keeps
        // the fall, and so the settle, the same length.
        static void Pile(World w, int count)
        {
            const float pitch = 1.8f;
            int side = (int)Math.Ceiling(Math.Sqrt(count / 6.0));
            for (int n = 0; n < count; n++)
            {
                int x = n % side, z = n / side % side, y = n / (side * side);
                float shift = (y & 1) * 0.5f * pitch;
                var at = new Vector3(pitch * (x - 0.5f * side) + shift, 1f + pitch * y, pitch * (z - 0.5f * side) + shift);
                Box(w, at, Quaternion.CreateFromYawPitchRoll(Jitter(n, 1), Jitter(n, 2), Jitter(n, 3)));
            }
        }

        static float Jitter(int n, int salt)
        {
            uint h = (uint)(n * 73856093) ^ (uint)(salt * 19349663);
            h ^= h >> 13;
            h *= 0x5bd1e995;
            h ^= h >> 15;
            return MathF.PI * ((h & 0xffff) / 32767.5f - 1f);
        }

        static void Ragdolls(World w, int count)
        {
            int side = (int)Math.Ceiling(Math.Sqrt(count));
            for (int n = 0; n < count; n++)
                Ragdoll(w, new Vector3(1.5f * (n % side - 0.5f * side), 0.3f, 1.5f * (n / side - 0.5f * side)),
                    new Vector3(2f * Jitter(n, 4) / MathF.PI, 0, 2f * Jitter(n, 5) / MathF.PI));
        }

        // Eleven bodies, ten joints, standing (local y up), so each part's pose is a translation
        // and every anchor is the world joint point minus the part's origin. The upper body is
        // pushed sideways (push, m/s) so the doll falls instead of balancing on its legs.
        static void Ragdoll(World w, Vector3 at, Vector3 push)
        {
            BodyHandle pelvis = Capsule(w, at + new Vector3(0, 1.00f, 0), 0.15f, 0.05f, Vector3.Zero);
            BodyHandle torso = Capsule(w, at + new Vector3(0, 1.35f, 0), 0.17f, 0.15f, push);
            BodyDef hd = BodyDef.Dynamic(at + new Vector3(0, 1.76f, 0));
            hd.LinearVelocity = push;
            BodyHandle head = w.CreateBody(hd);
            w.AddShape(head, ShapeDef.Of(ShapeGeometry.Sphere(0.12f)));
            Cone(w, pelvis, torso, at + new Vector3(0, 1.17f, 0), 30, 20);
            Cone(w, torso, head, at + new Vector3(0, 1.64f, 0), 40, 40);
            for (int side = -1; side <= 1; side += 2)
            {
                BodyHandle thigh = Capsule(w, at + new Vector3(0.1f * side, 0.70f, 0), 0.08f, 0.15f, Vector3.Zero);
                BodyHandle shin = Capsule(w, at + new Vector3(0.1f * side, 0.25f, 0), 0.07f, 0.15f, Vector3.Zero);
                BodyHandle upperArm = Capsule(w, at + new Vector3(0.3f * side, 1.35f, 0), 0.06f, 0.12f, push);
                BodyHandle forearm = Capsule(w, at + new Vector3(0.3f * side, 1.00f, 0), 0.05f, 0.12f, push);
                Cone(w, pelvis, thigh, at + new Vector3(0.1f * side, 0.92f, 0), 45, 15);
                Hinge(w, thigh, shin, at + new Vector3(0.1f * side, 0.47f, 0), -130, 0);
                Cone(w, torso, upperArm, at + new Vector3(0.3f * side, 1.50f, 0), 80, 30);
                Hinge(w, upperArm, forearm, at + new Vector3(0.3f * side, 1.17f, 0), 0, 130);
            }
        }

        static BodyHandle Capsule(World w, Vector3 at, float radius, float halfHeight, Vector3 velocity)
        {
            BodyDef d = BodyDef.Dynamic(at);
            d.LinearVelocity = velocity;
            BodyHandle b = w.CreateBody(d);
            w.AddShape(b, ShapeDef.Of(ShapeGeometry.Capsule(radius, halfHeight)));
            return b;
        }

        static void Cone(World w, BodyHandle a, BodyHandle b, Vector3 point, float coneDeg, float twistDeg) =>
            w.CreateJoint(JointDef.ConeTwist(a, b, point - w.GetBody(a).Position, point - w.GetBody(b).Position,
                Vector3.UnitY, Vector3.UnitY, coneDeg, twistDeg));

        static void Hinge(World w, BodyHandle a, BodyHandle b, Vector3 point, float lowerDeg, float upperDeg)
        {
            JointDef d = JointDef.Hinge(a, b, point - w.GetBody(a).Position, point - w.GetBody(b).Position, Vector3.UnitX, Vector3.UnitX);
            d.LowerDeg = lowerDeg;
            d.UpperDeg = upperDeg;
            w.CreateJoint(d);
        }
    }
}
